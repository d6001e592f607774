// WebGPU's graph resources: one texture or buffer per pooled object, so what the backend
// creates is the plan's pooled figure (count and bytes) for every shipped config, with
// and without --no-alias; and each object has only the usages the graph declares — a
// pass that uses a resource in an undeclared way gets a Dawn validation error (the
// negative control), while the same graph with the usage declared stays silent. And the
// command line's mode: with errors_throw, a Dawn error is a DeviceError at the next submit.
#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/device_error.h"
#include "graph/rhi/webgpu/graph_resources.h"
#include "graph/rhi/webgpu/webgpu_device.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/shipped_configs.h"

namespace volgraph::testing {
namespace {

// A test pass declared by hand (no PassTable): its slots by name.
SlotHandle slot(const PassSetup& c, std::string_view name) { return {uint16_t(c.graph_pass().decl->slot_index(name))}; }

class WebGpuResources : public ::testing::Test {
 protected:
  void SetUp() override {
    register_builtin_passes(registry_);
    device_ = webgpu::WebGpuDevice::create({.errors_throw = false});
  }
  void TearDown() override {
    const std::vector<std::string> messages = device_->take_messages();
    EXPECT_TRUE(messages.empty()) << joined_messages(messages);
  }
  PassRegistry registry_;
  std::unique_ptr<webgpu::WebGpuDevice> device_;
};

TEST_F(WebGpuResources, CreatedObjectsAreThePlansPooledFigure) {
  for (const std::string& config : shipped_configs()) {
    Overrides o;
    o.size = kConfigTestSize;
    const LoadedConfig c = load_config(config_path(config), registry_, o);
    for (const CompileOptions& options : {CompileOptions{}, CompileOptions{.alias = false}}) {
      webgpu::WebGpuGraphResources resources(*device_, c.graph);
      const Plan plan = compile(c.graph, options, resources.requirements());
      resources.bind(plan);
      const ResourcePool pool = pool_resources(c.graph, plan);
      EXPECT_EQ(resources.created().transient_objects, pool.transient_objects) << config << " alias " << options.alias;
      EXPECT_EQ(resources.created().transient_bytes, pool.transient_bytes) << config << " alias " << options.alias;
      EXPECT_EQ(resources.created().transient_bytes, options.alias ? pool.transient_bytes : plan.memory.unaliased_bytes)
          << config;
    }
  }
}

// Copies its `source` into `copy` although the slot says it only samples `source`.
class UndeclaredCopyExecution final : public PassExecution {
 public:
  void record(PassContext& c) override { c.encoder.copy_texture_to_texture(c.texture(slot(c, "source")), c.texture(slot(c, "copy"))); }
};

PassDecl copy_declared_as(Usage source_usage) {
  PassDecl d;
  d.name = source_usage == Usage::copy_src ? "declared_copy" : "undeclared_copy";
  d.kind = PassKind::transfer;
  d.variants = {{"full", ""}};
  d.slots = {slot_in("source", ResourceKind::texture2d, source_usage, ""),
             slot_out_like("copy", "source", Usage::copy_dst, "")};
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new UndeclaredCopyExecution()); };
  return d;
}

std::vector<std::string> messages_of_copy(webgpu::WebGpuDevice& device, PassRegistry& registry, Usage source_usage) {
  const PassDecl decl = copy_declared_as(source_usage);
  registry.add(decl);
  const std::string text = R"({ "output": { "size": [8, 8] }, "graph": { "passes": [
      { "name": "c", "type": "clear" },
      { "name": "k", "type": ")" + decl.name + R"(", "inputs": { "source": "c.target" } }
    ], "outputs": ["k.copy"] } })";
  const LoadedConfig c = load_config_text("copy.json", text, registry);
  Executor executor(device, c.graph, &c.config.scene, {});
  executor.run_frame();
  return device.take_messages();
}

TEST_F(WebGpuResources, AnUndeclaredUsageIsADawnValidationError) {
  const std::vector<std::string> messages = messages_of_copy(*device_, registry_, Usage::sampled);
  ASSERT_FALSE(messages.empty()) << "the source was declared sampled only, yet copying it passed";
  EXPECT_NE(joined_messages(messages).find("CopySrc"), std::string::npos) << joined_messages(messages);
}

TEST_F(WebGpuResources, TheSameCopyDeclaredIsSilent) {
  EXPECT_TRUE(messages_of_copy(*device_, registry_, Usage::copy_src).empty());
}

TEST(WebGpuErrors, ADawnErrorThrowsAtTheNextSubmitWhenAsked) {
  const auto device = webgpu::WebGpuDevice::create({.errors_throw = true});
  device->create_texture({"no usage", ResourceKind::texture2d, Format::rgba8_unorm, {4, 4, 1}, 0});  // WebGPU refuses usage 0
  try {
    device->submit(device->create_command_encoder("after the error"));
    FAIL() << "expected a DeviceError";
  } catch (const DeviceError& e) {
    EXPECT_EQ(e.kind, DeviceError::Kind::other);
    EXPECT_NE(std::string(e.what()).find("Dawn validation error"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(device->submit(device->create_command_encoder("reported once")));
}

}  // namespace
}  // namespace volgraph::testing
