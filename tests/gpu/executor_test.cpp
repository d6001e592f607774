// The executor runs a compiled plan through the backend interface: exact values for a
// graph whose answer is known, the same image under every debug switch, tone maps equal
// to the CPU twin, GPU times per pass, validation silent.
#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/passes.h"
#include "passes/shading/tonemap.h"
#include "tests/gpu/validation_messages.h"

namespace volgraph::vulkan {
namespace {

class ExecutorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    register_builtin_passes(registry_);
    context_ = Context::create({.validation = true});
    device_ = std::make_unique<VulkanDevice>(*context_);
  }
  void TearDown() override {
    device_.reset();
    const auto messages = context_->take_validation_messages();
    EXPECT_TRUE(messages.empty()) << joined(messages);
  }
  LoadedConfig load(const Overrides& o = {}) {
    return load_config(std::string(VOLGRAPH_SOURCE_DIR) + "/configs/tests/clear_composite.json", registry_, o);
  }
  Texels render(const LoadedConfig& c, const CompileOptions& options, int frames = 1) {
    Executor executor(*device_, c.graph, &c.config.scene, options);
    for (int f = 0; f < frames; ++f) executor.run_frame();
    last_timings_ = executor.timings();
    return executor.read_output(0);
  }

  PassRegistry registry_;
  std::unique_ptr<Context> context_;
  std::unique_ptr<VulkanDevice> device_;
  std::vector<PassTiming> last_timings_;
};

TEST_F(ExecutorTest, ClearedRadianceComesOutExactly) {
  const Texels t = render(load(), {});
  ASSERT_EQ(t.width, 40u);
  ASSERT_EQ(t.height, 24u);
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    ASSERT_EQ(t.rgba[i + 0], 0.5f) << i;
    ASSERT_EQ(t.rgba[i + 1], 0.25f) << i;
    ASSERT_EQ(t.rgba[i + 2], 2.0f) << i;
    ASSERT_EQ(t.rgba[i + 3], 1.0f) << i;
  }
  ASSERT_EQ(last_timings_.size(), 3u);  // unused_branch is culled
  for (const PassTiming& p : last_timings_) {
    EXPECT_GT(p.gpu_ms, 0.0) << p.pass;
    EXPECT_GE(p.cpu_ms, 0.0) << p.pass;
  }
}

TEST_F(ExecutorTest, DebugSwitchesGiveTheSameImage) {
  const LoadedConfig c = load();
  const Texels reference = render(c, {});
  for (const CompileOptions& o : {CompileOptions{.cull = false}, CompileOptions{.alias = false}, CompileOptions{.serialize = true}}) {
    EXPECT_EQ(render(c, o).rgba, reference.rgba) << "cull " << o.cull << " alias " << o.alias << " serialize " << o.serialize;
  }
}

TEST_F(ExecutorTest, ToneMapsMatchTheCpuTwinOverSeveralFrames) {
  for (const char* variant : {"aces", "reinhard"}) {
    Overrides o;
    o.variants = {std::string("out=") + variant};
    o.sets = {"out.exposure=0.5"};
    const Texels t = render(load(o), {}, 3);
    const shading::Rgb want = shading::tone_map({0.5, 0.25, 2.0}, 0.5,
                                                std::string(variant) == "aces" ? shading::ToneMap::aces : shading::ToneMap::reinhard);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(t.rgba[size_t(ch)], want[size_t(ch)], 1e-5 * want[size_t(ch)]) << variant;
  }
}

TEST_F(ExecutorTest, APassWithoutAnImplementationIsNamed) {
  const LoadedConfig c = load_config(std::string(VOLGRAPH_SOURCE_DIR) + "/configs/demo_point_lights.json", registry_);
  try {
    Executor executor(*device_, c.graph, &c.config.scene, {});
    FAIL() << "expected a DeviceError";
  } catch (const DeviceError& e) {
    EXPECT_EQ(e.kind, DeviceError::Kind::unsupported);
    EXPECT_NE(std::string(e.what()).find("pass \"lit\" (scene) has no GPU implementation yet"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volgraph::vulkan
