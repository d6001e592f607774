// Whole plans run on lavapipe with exactly the plan's barriers, under synchronization
// validation. The passes use only what needs no shader — attachments through dynamic
// rendering, copies, fills — so random graphs of them exercise ordering, layouts,
// aliasing hand-overs and --serialize for real. Each pass writes values a CPU model
// predicts; every graph output is read back and compared, so a resource whose bytes
// were handed over too early (aliasing leaking contents) fails the test.
#include <algorithm>
#include <functional>
#include <cstring>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "graph/rhi/vulkan/barriers.h"
#include "graph/rhi/vulkan/graph_resources.h"

namespace volgraph::vulkan {
namespace {

constexpr auto k2D = ResourceKind::texture2d;
constexpr auto kBuffer = ResourceKind::buffer;

PassDecl decl(const char* name, PassKind kind, std::vector<SlotDecl> slots) {
  PassDecl d;
  d.name = name;
  d.kind = kind;
  d.variants = {{"default", ""}};
  d.slots = std::move(slots);
  return d;
}

struct Decls {
  // draw: clears a new colour and depth attachment (the value is the pass's).
  PassDecl draw = decl("draw", PassKind::graphics,
                       {slot_out("color", k2D, Usage::color_attachment, Format::rgba16_float, SizeSpec::fixed(32, 32), ""),
                        slot_out("depth", k2D, Usage::depth_attachment, Format::d32_float, SizeSpec::fixed(32, 32), "")});
  // blend: loads a colour attachment and overwrites it inside the render pass.
  PassDecl blend = decl("blend", PassKind::graphics, {slot_inout("color", k2D, Usage::color_attachment_load, "")});
  PassDecl copy = decl("copy", PassKind::transfer,
                       {slot_in("source", k2D, Usage::copy_src, ""),
                        slot_out("copy", k2D, Usage::copy_dst, Format::rgba16_float, SizeSpec::fixed(32, 32), "")});
  PassDecl fill = decl("fill", PassKind::transfer,
                       {slot_out("buffer", kBuffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(4096), "")});
  PassDecl buffer_copy = decl("buffer_copy", PassKind::transfer,
                              {slot_in("source", kBuffer, Usage::copy_src, ""),
                               slot_out("copy", kBuffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(4096), "")});
};

// A random graph of those passes, with the value every resource version holds.
struct Scenario {
  Graph graph;
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> value;  // (resource, version) → value
  std::vector<uint32_t> pass_value;                         // what each pass writes
};

Scenario make_scenario(const Decls& d, uint64_t seed, uint32_t passes) {
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
  s.pass_value.resize(passes);
  const uint32_t sizes[][2] = {{16, 16}, {32, 32}, {48, 24}, {64, 64}};
  for (uint32_t step = 0; step < passes; ++step) {
    const uint32_t p = declared[step];
    const PassDecl* k = kinds[step];
    const uint32_t v = 1 + step;  // exact in fp16 and as an integer
    s.pass_value[p] = v;
    if (k == &d.blend && colors.empty()) k = &d.draw;
    if (k == &d.copy && colors.empty()) k = &d.draw;
    if (k == &d.buffer_copy && buffers.empty()) k = &d.fill;
    if (k != kinds[step]) {  // fall back: rebuild the pass with the kind it really is
      b.graph().passes[p].decl = k;
      b.graph().passes[p].kind = k->kind;
    }
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
      colors[i] = b.modify(p, 0, colors[i]);
      s.value[{colors[i].resource, colors[i].version}] = v;
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

uint32_t slot_resource(const GraphPass& p, uint16_t slot) {
  for (const ResourceUse& u : p.uses) {
    if (u.slot == slot) return u.resource;
  }
  return kNone;
}

VkRenderingAttachmentInfo attachment(VkImageView view, VkImageLayout layout, VkAttachmentLoadOp load, VkClearValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = load;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue = clear;
  return a;
}

// What each pass does, in the stages and accesses its slots declare.
void record_pass(VkCommandBuffer cmd, const Decls& d, const Graph& g, uint32_t p, float value, const GraphResources& res) {
  const GraphPass& pass = g.passes[p];
  if (pass.decl == &d.draw || pass.decl == &d.blend) {
    const uint32_t color = slot_resource(pass, 0);
    const Extent e = g.resources[color].desc.extent;
    const bool draw = pass.decl == &d.draw;
    VkClearValue clear{};
    clear.color = {{value, value, value, 1.0f}};
    VkRenderingAttachmentInfo c = attachment(res.view(color), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                             draw ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD, clear);
    VkClearValue depth_clear{};
    depth_clear.depthStencil = {1.0f, 0};
    VkRenderingAttachmentInfo z{};
    if (draw) z = attachment(res.view(slot_resource(pass, 1)), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                             VK_ATTACHMENT_LOAD_OP_CLEAR, depth_clear);
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {e.width, e.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = 1;
    info.pColorAttachments = &c;
    info.pDepthAttachment = draw ? &z : nullptr;
    vkCmdBeginRendering(cmd, &info);
    if (!draw) {  // overwrite what was loaded
      VkClearAttachment ca{VK_IMAGE_ASPECT_COLOR_BIT, 0, clear};
      VkClearRect rect{{{0, 0}, {e.width, e.height}}, 0, 1};
      vkCmdClearAttachments(cmd, 1, &ca, 1, &rect);
    }
    vkCmdEndRendering(cmd);
    return;
  }
  if (pass.decl == &d.copy) {
    const uint32_t src = slot_resource(pass, 0), dst = slot_resource(pass, 1);
    const Extent e = g.resources[src].desc.extent;
    VkImageCopy region{{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {}, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {}, {e.width, e.height, 1}};
    vkCmdCopyImage(cmd, res.image(src), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, res.image(dst),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    return;
  }
  if (pass.decl == &d.fill) {
    vkCmdFillBuffer(cmd, res.buffer(slot_resource(pass, 0)), 0, VK_WHOLE_SIZE, uint32_t(value));
    return;
  }
  const uint32_t src = slot_resource(pass, 0), dst = slot_resource(pass, 1);
  VkBufferCopy region{0, 0, g.resources[src].desc.buffer_bytes};
  vkCmdCopyBuffer(cmd, res.buffer(src), res.buffer(dst), 1, &region);
}

float half_to_float(uint16_t h) {
  const uint32_t sign = uint32_t(h >> 15) << 31, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  uint32_t bits;
  if (exponent == 0) bits = sign;  // zero (no denormals in these values)
  else if (exponent == 31) bits = sign | 0x7f800000u | (mantissa << 13);
  else bits = sign | ((exponent + 112) << 23) | (mantissa << 13);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

class PlanExecution : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = Context::create({.validation = true}).release(); }
  static void TearDownTestSuite() { delete context_; }
  static Context* context_;
};
Context* PlanExecution::context_ = nullptr;

// Runs the scenario's plan (after `tamper`, for the negative controls) and returns ""
// or what went wrong.
std::string run(Context& c, const Decls& d, const Scenario& s, const CompileOptions& options,
                const std::function<void(Plan&)>& tamper = {}) {
  const Graph& g = s.graph;
  GraphResources res(c, g);
  Plan plan = compile(g, options, res.requirements());
  if (tamper) tamper(plan);
  res.bind(plan);

  // Host buffer for every live output's contents.
  std::vector<std::pair<uint32_t, VkDeviceSize>> outputs;  // resource, offset
  VkDeviceSize total = 0;
  for (const ResourceVersion& o : g.outputs) {
    if (plan.lifetimes[o.resource].first == kNone) continue;
    outputs.push_back({o.resource, total});
    total += (content_bytes(g.resources[o.resource].desc) + 15) / 16 * 16;
  }
  VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bi.size = std::max<VkDeviceSize>(total, 16);
  bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  VkBuffer host = VK_NULL_HANDLE;
  check(vkCreateBuffer(c.device(), &bi, nullptr, &host), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(c.device(), host, &req);
  VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = c.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  VkDeviceMemory host_memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(c.device(), &ai, nullptr, &host_memory), "vkAllocateMemory");
  check(vkBindBufferMemory(c.device(), host, host_memory, 0), "vkBindBufferMemory");

  c.submit_and_wait([&](VkCommandBuffer cmd) {
    for (uint32_t pos = 0; pos < plan.order.size(); ++pos) {
      record_barriers(cmd, g, plan, pos, res);
      const uint32_t p = plan.order[pos].pass;
      record_pass(cmd, d, g, p, float(s.pass_value[p]), res);
    }
    // Readback: everything done, outputs to transfer-source layout.
    for (const auto& [r, offset] : outputs) {
      const ResourceDesc& desc = g.resources[r].desc;
      VkMemoryBarrier2 all{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2, nullptr, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                           VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
      VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
      if (desc.kind == kBuffer) {
        dep.memoryBarrierCount = 1;
        dep.pMemoryBarriers = &all;
        vkCmdPipelineBarrier2(cmd, &dep);
        VkBufferCopy region{0, offset, desc.buffer_bytes};
        vkCmdCopyBuffer(cmd, res.buffer(r), host, 1, &region);
        continue;
      }
      // The image is in the layout of its last use: the last barrier that named it says which.
      Layout last = Layout::undefined;
      for (const Barrier& b : plan.barriers) {
        if (b.resource == r) last = b.to.layout;
      }
      VkImageMemoryBarrier2 ib{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
      ib.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
      ib.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
      ib.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
      ib.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
      ib.oldLayout = to_vk(last);
      ib.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
      ib.srcQueueFamilyIndex = ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      ib.image = res.image(r);
      ib.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      dep.imageMemoryBarrierCount = 1;
      dep.pImageMemoryBarriers = &ib;
      vkCmdPipelineBarrier2(cmd, &dep);
      VkBufferImageCopy region{offset, 0, 0, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {}, {desc.extent.width, desc.extent.height, 1}};
      vkCmdCopyImageToBuffer(cmd, res.image(r), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host, 1, &region);
    }
  });

  std::string problems;
  void* mapped = nullptr;
  check(vkMapMemory(c.device(), host_memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  for (const auto& [r, offset] : outputs) {
    const ResourceDesc& desc = g.resources[r].desc;
    const uint32_t version = uint32_t(g.resources[r].version_writers.size() - 1);
    const uint32_t expected = s.value.at({r, version});
    const char* base = static_cast<const char*>(mapped) + offset;
    const size_t texels = desc.kind == kBuffer ? desc.buffer_bytes / 4 : size_t(desc.extent.width) * desc.extent.height;
    size_t wrong = 0;
    for (size_t t = 0; t < texels; ++t) {
      if (desc.kind == kBuffer) {
        uint32_t v;
        std::memcpy(&v, base + 4 * t, 4);
        wrong += v != expected;
      } else {
        uint16_t h;
        std::memcpy(&h, base + 8 * t, 2);  // red channel of rgba16_float
        wrong += half_to_float(h) != float(expected);
      }
    }
    if (wrong) problems += desc.name + ": " + std::to_string(wrong) + " of " + std::to_string(texels) + " texels wrong\n";
  }
  vkUnmapMemory(c.device(), host_memory);
  vkDestroyBuffer(c.device(), host, nullptr);
  vkFreeMemory(c.device(), host_memory, nullptr);
  for (const std::string& m : c.take_validation_messages()) problems += "validation: " + m + "\n";
  return problems;
}

TEST_F(PlanExecution, RandomPlansRunCleanAndKeepEveryOutputIntact) {
  const Decls d;
  size_t handovers = 0;
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    const Scenario s = make_scenario(d, seed, 12 + uint32_t(seed % 5) * 6);
    for (const CompileOptions& options : {CompileOptions{}, CompileOptions{.alias = false}, CompileOptions{.serialize = true}}) {
      const std::string problems = run(*context_, d, s, options);
      EXPECT_EQ(problems, "") << "seed " << seed << " alias " << options.alias << " serialize " << options.serialize;
    }
    handovers += compile(s.graph).handovers.size();
  }
  EXPECT_GT(handovers, 24u) << "the scenarios should exercise aliasing";
}

// Negative controls: the checks above can fail.
TEST_F(PlanExecution, WithoutThePlansBarriersTheLayerReportsHazards) {
  const Decls d;
  const Scenario s = make_scenario(d, 7, 24);
  const std::string problems = run(*context_, d, s, {}, [](Plan& plan) {
    for (PlannedPass& p : plan.order) p.barrier_count = 0;
  });
  EXPECT_NE(problems.find("validation: "), std::string::npos) << problems;
}

TEST_F(PlanExecution, ResourcesSharingBytesWhileAliveCorruptOutputs) {
  const Decls d;
  size_t corrupted = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    const Scenario s = make_scenario(d, seed, 24);
    const std::string problems = run(*context_, d, s, {.alias = false}, [](Plan& plan) {
      for (Placement& p : plan.placements) p.offset = 0;  // everything on top of everything, barriers kept
    });
    corrupted += problems.find("texels wrong") != std::string::npos;
  }
  EXPECT_GT(corrupted, 0u) << "overlapping live resources must show in the read-back values";
}

}  // namespace
}  // namespace volgraph::vulkan
