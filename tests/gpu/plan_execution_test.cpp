// Whole plans run through the executor on lavapipe, with exactly the plan's barriers,
// under synchronization validation. The test's own pass types (a local registry) talk
// to the backend interface only: render passes that clear or load attachments (a load
// then adds the pass's value with an additive draw), texture and buffer copies, buffer
// updates — so random graphs of them exercise ordering, layouts, aliasing hand-overs
// and --serialize for real. Each pass writes values a CPU model predicts; every graph
// output is read back and compared, so a resource whose bytes were handed over too
// early (aliasing leaking contents) fails the test. The negative controls run plans
// edited through the executor's run-this-plan entry point.
#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "graph/execute/executor.h"
#include "graph/registry.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "shaders/shader_library.h"

namespace volgraph::vulkan {
namespace {

constexpr auto k2D = ResourceKind::texture2d;
constexpr auto kBuffer = ResourceKind::buffer;

// These test passes are declared by hand (no PassTable): their slots and parameter by name.
SlotHandle slot(const PassSetup& c, std::string_view name) { return {uint16_t(c.graph_pass().decl->slot_index(name))}; }
float value_of(const PassContext& c) {
  return float(c.param(ParamHandle<double>{uint16_t(c.graph_pass().decl->param_index("value"))}));
}

// draw: clears a new colour attachment to the pass's value and a new depth attachment.
class DrawExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    const float v = value_of(c);
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name;
    pass.colors = {{c.view(slot(c, "color")), rhi::LoadOp::clear, {v, v, v, 1.0f}}};
    pass.depth = {c.view(slot(c, "depth")), rhi::LoadOp::clear, 1.0f};
    c.encoder.begin_render_pass(pass);
    c.encoder.end_render_pass();
  }
};

// What every blend pass draws with: one pipeline for all (one per pass made this test
// several times slower on lavapipe), a triangle covering any target, and per value
// added a uniform block (value, value, value, 0).
class BlendPipeline {
 public:
  // Binds the pipeline, the block adding `value` and the triangle, for draw(3).
  void bind(rhi::Device& device, rhi::CommandEncoder& encoder, float value) {
    make_for(device);
    encoder.set_pipeline(pipeline_);
    encoder.set_bind_group(0, group_adding(device, value));
    encoder.set_vertex_buffer(0, triangle_);
  }

 private:
  void make_for(rhi::Device& device) {
    if (device_ == &device) return;
    using namespace rhi;
    device_ = &device;
    groups_.clear();
    layout_ = device.create_bind_group_layout({"blend", {{0, shader_stage::fragment, BindingType::uniform_buffer}}});
    RenderPipelineDesc pd;
    pd.label = "blend";
    pd.vertex_module = device.create_shader_module("flat_color.vert", shader_spirv("flat_color.vert"));
    pd.fragment_module = device.create_shader_module("flat_color.frag", shader_spirv("flat_color.frag"));
    pd.vertex_buffers = {{12, {{0, VertexFormat::float32x3, 0}}}};
    pd.colors = {{Format::rgba16_float, BlendMode::additive}};
    pd.layouts = {layout_};
    pipeline_ = device.create_render_pipeline(pd);
    const float corners[] = {-1, -1, 0, 3, -1, 0, -1, 3, 0};
    triangle_ = device.create_buffer({"covering triangle", sizeof corners, buffer_usage::vertex});
    device.write_buffer(triangle_, 0, std::as_bytes(std::span(corners)));
  }

  rhi::BindGroupId group_adding(rhi::Device& device, float value) {
    auto [it, added] = groups_.try_emplace(value);
    if (!added) return it->second;
    const float color[] = {value, value, value, 0.0f};
    rhi::BindGroupEntry entry;
    entry.buffer = device.create_buffer({"blend colour", sizeof color, rhi::buffer_usage::uniform});
    device.write_buffer(entry.buffer, 0, std::as_bytes(std::span(color)));
    it->second = device.create_bind_group({"blend", layout_, {entry}});
    return it->second;
  }

  const rhi::Device* device_ = nullptr;  // the one the handles belong to
  rhi::BindGroupLayoutId layout_;
  rhi::RenderPipelineId pipeline_;
  rhi::BufferId triangle_;
  std::map<float, rhi::BindGroupId> groups_;
};

// blend: loads a colour attachment and adds the pass's value to every texel's RGB
// (additive blending): what it loaded shows in what it stores.
class BlendExecution final : public PassExecution {
 public:
  explicit BlendExecution(std::shared_ptr<BlendPipeline> shared) : shared_(std::move(shared)) {}

  void record(PassContext& c) override {
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name;
    pass.colors = {{c.view(slot(c, "color")), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    shared_->bind(c.device, c.encoder, value_of(c));
    c.encoder.draw(3);
    c.encoder.end_render_pass();
  }

 private:
  std::shared_ptr<BlendPipeline> shared_;
};

class CopyExecution final : public PassExecution {
 public:
  void record(PassContext& c) override { c.encoder.copy_texture_to_texture(c.texture(slot(c, "source")), c.texture(slot(c, "copy"))); }
};

// fill: every 32-bit word of a new buffer set to the pass's value.
class FillExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    const std::vector<uint32_t> words(c.desc(slot(c, "buffer")).buffer_bytes / 4, uint32_t(value_of(c)));
    c.encoder.update_buffer(c.buffer(slot(c, "buffer")), 0, std::as_bytes(std::span(words)));
  }
};

class BufferCopyExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    c.encoder.copy_buffer_to_buffer(c.buffer(slot(c, "source")), c.buffer(slot(c, "copy")), c.desc(slot(c, "source")).buffer_bytes);
  }
};

template <typename T>
std::unique_ptr<PassExecution> make() {
  return std::make_unique<T>();
}

// A pass type of this test; `valued` ones write the value of their "value" parameter.
PassDecl decl(const char* name, PassKind kind, std::vector<SlotDecl> slots, bool valued, MakeExecution make_execution) {
  PassDecl d;
  d.name = name;
  d.kind = kind;
  d.variants = {{"default", ""}};
  if (valued) d.params = {param_number("value", 0, 0, 1e6, "", "what the pass writes")};
  d.slots = std::move(slots);
  d.make_execution = make_execution;
  return d;
}

struct TestPasses {
  const PassDecl& draw;
  const PassDecl& blend;
  const PassDecl& copy;
  const PassDecl& fill;
  const PassDecl& buffer_copy;
};

TestPasses register_test_passes(PassRegistry& registry) {
  return {
      registry.add(decl("draw", PassKind::graphics,
                        {slot_out("color", k2D, Usage::color_attachment, Format::rgba16_float, SizeSpec::fixed(32, 32), ""),
                         slot_out("depth", k2D, Usage::depth_attachment, Format::d32_float, SizeSpec::fixed(32, 32), "")},
                        true, &make<DrawExecution>)),
      registry.add(decl("blend", PassKind::graphics, {slot_inout("color", k2D, Usage::color_attachment_load, "")}, true,
                        [shared = std::make_shared<BlendPipeline>()] { return std::make_unique<BlendExecution>(shared); })),
      registry.add(decl("copy", PassKind::transfer,
                        {slot_in("source", k2D, Usage::copy_src, ""),
                         slot_out("copy", k2D, Usage::copy_dst, Format::rgba16_float, SizeSpec::fixed(32, 32), "")},
                        false, &make<CopyExecution>)),
      registry.add(decl("fill", PassKind::transfer,
                        {slot_out("buffer", kBuffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(4096), "")}, true,
                        &make<FillExecution>)),
      registry.add(decl("buffer_copy", PassKind::transfer,
                        {slot_in("source", kBuffer, Usage::copy_src, ""),
                         slot_out("copy", kBuffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(4096), "")},
                        false, &make<BufferCopyExecution>)),
  };
}

// A random graph of those passes, with the value every resource version holds.
struct Scenario {
  Graph graph;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> value;  // (resource, version) → value
};

Scenario make_scenario(const TestPasses& d, uint64_t seed, uint32_t passes) {
  std::mt19937_64 rng(seed);
  auto below = [&](uint64_t n) { return uint32_t(rng() % n); };
  // Pass p copies one of `latest` (slot 0) into a new resource like it (slot 1).
  auto copy_from = [&](GraphBuilder& b, uint32_t p, std::vector<ResourceVersion>& latest, Scenario& s) {
    const ResourceVersion src = latest[below(latest.size())];
    b.read(p, 0, src);
    ResourceDesc desc = b.graph().resources[src.resource].desc;
    desc.name.clear();
    const ResourceVersion c = b.create(p, 1, desc);
    latest.push_back(c);
    s.value[{c.resource, 0}] = s.value[{src.resource, src.version}];
  };
  std::vector<const PassDecl*> kinds(passes);
  for (uint32_t i = 0; i < passes; ++i) {
    const uint32_t k = below(100);
    kinds[i] = i == 0 || k < 35 ? &d.draw : k < 55 ? &d.blend : k < 80 ? &d.copy : k < 92 ? &d.fill : &d.buffer_copy;
  }
  std::vector<uint32_t> declared(passes);  // construction step → pass index (declaration order shuffled)
  for (uint32_t i = 0; i < passes; ++i) declared[i] = i;
  std::shuffle(declared.begin(), declared.end(), rng);
  std::vector<uint32_t> step_of(passes);
  for (uint32_t i = 0; i < passes; ++i) step_of[declared[i]] = i;

  Scenario s;
  GraphBuilder b({32, 32, 1}, 0);
  for (uint32_t p = 0; p < passes; ++p) b.add_pass("p" + std::to_string(p), *kinds[step_of[p]]);
  std::vector<ResourceVersion> colors, buffers;  // latest versions
  const uint32_t sizes[][2] = {{16, 16}, {32, 32}, {48, 24}, {64, 64}};
  for (uint32_t step = 0; step < passes; ++step) {
    const uint32_t p = declared[step];
    const PassDecl* k = kinds[step];
    const uint32_t v = 1 + step;  // sums of these stay exact in fp16
    if (k == &d.blend && colors.empty()) k = &d.draw;
    if (k == &d.copy && colors.empty()) k = &d.draw;
    if (k == &d.buffer_copy && buffers.empty()) k = &d.fill;
    GraphPass& pass = b.graph().passes[p];
    pass.decl = k;  // the kind it really is, after the fall-backs above
    pass.kind = k->kind;
    if (!k->params.empty()) pass.params = {ParamValue(double(v))};
    if (k == &d.draw) {
      const auto& sz = sizes[below(4)];
      ResourceDesc color{"", k2D, Format::rgba16_float, {sz[0], sz[1], 1}, 0, false};
      ResourceDesc depth{"", k2D, Format::d32_float, {sz[0], sz[1], 1}, 0, false};
      const ResourceVersion c = b.create(p, 0, color);
      b.create(p, 1, depth);
      colors.push_back(c);
      s.value[{c.resource, 0}] = v;
    } else if (k == &d.blend) {
      const uint32_t i = below(colors.size());
      const uint32_t loaded = s.value[{colors[i].resource, colors[i].version}];
      colors[i] = b.modify(p, 0, colors[i]);
      s.value[{colors[i].resource, colors[i].version}] = loaded + v;
    } else if (k == &d.copy) {
      copy_from(b, p, colors, s);
    } else if (k == &d.fill) {
      const ResourceVersion f = b.create(p, 0, {"", kBuffer, Format::undefined, {}, 1024u * (1 + below(8)), false});
      buffers.push_back(f);
      s.value[{f.resource, 0}] = v;
    } else {
      copy_from(b, p, buffers, s);
    }
  }
  // Outputs: the last colour and buffer, and a third of the rest; other passes get culled.
  b.mark_output(colors.back());
  if (!buffers.empty()) b.mark_output(buffers.back());
  for (const auto& list : {colors, buffers}) {
    for (const ResourceVersion& r : list) {
      if (below(3) == 0) b.mark_output(r);
    }
  }
  s.graph = b.finish();
  return s;
}

// Texels whose RGB is not `expected` or whose alpha is not 1.
size_t wrong_texels(const Texels& t, float expected) {
  size_t wrong = 0;
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    wrong += t.rgba[i] != expected || t.rgba[i + 1] != expected || t.rgba[i + 2] != expected || t.rgba[i + 3] != 1.0f;
  }
  return wrong;
}

size_t wrong_words(const std::vector<std::byte>& bytes, size_t words, uint32_t expected) {
  if (bytes.size() < 4 * words) return words;
  size_t wrong = 0;
  for (size_t w = 0; w < words; ++w) {
    uint32_t v;
    std::memcpy(&v, bytes.data() + 4 * w, 4);
    wrong += v != expected;
  }
  return wrong;
}

// "" or which graph outputs, read back after the frame, hold other values than the model's.
std::string wrong_outputs(const Scenario& s, const std::vector<uint32_t>& outputs, const std::vector<Readback>& read) {
  std::string problems;
  for (size_t i = 0; i < outputs.size(); ++i) {
    const GraphResource& r = s.graph.resources[outputs[i]];
    const uint32_t expected = s.value.at({outputs[i], uint32_t(r.version_writers.size() - 1)});
    const bool buffer = r.desc.kind == kBuffer;
    const size_t values = buffer ? r.desc.buffer_bytes / 4 : size_t(r.desc.extent.width) * r.desc.extent.height;
    const size_t wrong = buffer ? wrong_words(read[i].bytes, values, expected) : wrong_texels(read[i].texels, float(expected));
    if (wrong) problems += r.desc.name + ": " + std::to_string(wrong) + " of " + std::to_string(values) + " values wrong\n";
  }
  return problems;
}

// The executor for the scenario's plan, or for that plan after `edit` (negative controls).
std::unique_ptr<Executor> executor_for(rhi::Device& device, const Graph& graph, const CompileOptions& options,
                                       const std::function<void(Plan&)>& edit) {
  if (!edit) return std::make_unique<Executor>(device, graph, nullptr, options);
  Plan plan = Executor::compile_for(device, graph, options);
  edit(plan);
  return Executor::for_plan(device, graph, nullptr, std::move(plan));
}

class PlanExecution : public ::testing::Test {
 protected:
  void SetUp() override {
    context_ = Context::create({.validation = true});
    device_ = std::make_unique<VulkanDevice>(*context_);
  }
  void TearDown() override { device_.reset(); }

  // Runs one frame of the scenario's plan (edited first when `edit` is given) and
  // returns "" or what went wrong: outputs off the model, validation messages.
  std::string run(const Scenario& s, const CompileOptions& options, const std::function<void(Plan&)>& edit = {}) {
    const std::unique_ptr<Executor> executor = executor_for(*device_, s.graph, options, edit);
    executor->set_gpu_timing(false);  // as a frame runs without profiling
    std::vector<uint32_t> outputs;
    for (const ResourceVersion& o : s.graph.outputs) outputs.push_back(o.resource);
    std::string problems = wrong_outputs(s, outputs, executor->run_frame_and_read(outputs));
    for (const std::string& m : context_->take_validation_messages()) problems += "validation: " + m + "\n";
    return problems;
  }

  PassRegistry registry_;
  const TestPasses passes_ = register_test_passes(registry_);
  std::unique_ptr<Context> context_;
  std::unique_ptr<VulkanDevice> device_;
};

TEST_F(PlanExecution, RandomPlansRunCleanAndKeepEveryOutputIntact) {
  size_t handovers = 0;
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    const Scenario s = make_scenario(passes_, seed, 12 + uint32_t(seed % 5) * 6);
    for (const CompileOptions& options : {CompileOptions{}, CompileOptions{.alias = false}, CompileOptions{.serialize = true}}) {
      EXPECT_EQ(run(s, options), "") << "seed " << seed << " alias " << options.alias << " serialize " << options.serialize;
    }
    handovers += compile(s.graph).handovers.size();
  }
  EXPECT_GT(handovers, 24u) << "the scenarios should exercise aliasing";
}

// Negative controls: the checks above can fail.
TEST_F(PlanExecution, WithoutThePlansBarriersTheLayerReportsHazards) {
  const Scenario s = make_scenario(passes_, 7, 24);
  const std::string problems = run(s, {}, [](Plan& plan) {
    for (PlannedPass& p : plan.order) p.barrier_count = 0;
  });
  EXPECT_NE(problems.find("validation: SYNC-HAZARD-"), std::string::npos) << problems;
}

TEST_F(PlanExecution, ResourcesSharingBytesWhileAliveCorruptOutputs) {
  size_t corrupted = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    const Scenario s = make_scenario(passes_, seed, 24);
    const std::string problems = run(s, {.alias = false}, [](Plan& plan) {
      for (Placement& p : plan.placements) p.offset = 0;  // everything on top of everything, barriers kept
    });
    corrupted += problems.find("values wrong") != std::string::npos;
  }
  EXPECT_GT(corrupted, 0u) << "overlapping live resources must show in the read-back values";
}

TEST_F(PlanExecution, APlanRunsOnlyOnItsOwnGraph) {
  const Scenario small = make_scenario(passes_, 3, 12), large = make_scenario(passes_, 3, 24);
  EXPECT_THROW(Executor::for_plan(*device_, large.graph, nullptr, Executor::compile_for(*device_, small.graph, {})),
               std::invalid_argument);
}

}  // namespace
}  // namespace volgraph::vulkan
