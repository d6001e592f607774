// Every shipped config (configs/*.json, configs/tests/*.json) renders on lavapipe with
// the validation layer silent and:
// - the same image, bit for bit, under each of the plan's debug switches (--no-cull,
//   --no-alias, --serialize): culling and aliasing never change what is drawn;
// - no NaN or Inf in its output;
// - an image close to its golden image (tests/golden/): relative mean absolute error
//   ≤ 1 % and at most 0.5 % of pixels off by more than 5 % (tests/support/image_compare.h).
// Goldens are rewritten with VOLGRAPH_UPDATE_GOLDEN=1; look at them before committing.
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/passes.h"
#include "tests/gpu/validation_messages.h"
#include "tests/support/image_compare.h"
#include "tools/image_io.h"

namespace volgraph::vulkan {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = VOLGRAPH_SOURCE_DIR;
const Extent kSize{64, 36, 1};  // small: the suite runs on two CPU cores

std::vector<std::string> shipped_configs() {
  std::vector<std::string> names;
  for (const char* folder : {"configs", "configs/tests"}) {
    for (const fs::directory_entry& e : fs::directory_iterator(kSource / folder)) {
      if (e.path().extension() == ".json") names.push_back(fs::relative(e.path(), kSource / "configs").string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = fs::path(info.param).replace_extension().string();
  for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return name;
}

class ConfigRender : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    register_builtin_passes(registry_);
    context_ = Context::create({.validation = true});
    device_ = std::make_unique<VulkanDevice>(*context_);
    Overrides o;
    o.size = kSize;
    config_ = std::make_unique<LoadedConfig>(load_config((kSource / "configs" / GetParam()).string(), registry_, o));
  }
  void TearDown() override {
    device_.reset();
    const auto messages = context_->take_validation_messages();
    EXPECT_TRUE(messages.empty()) << joined(messages);
  }
  Texels render(const CompileOptions& options) {
    Executor executor(*device_, config_->graph, &config_->config.scene, options);
    executor.run_frame();
    return executor.read_output(0);
  }
  fs::path golden_path() const { return kSource / "tests/golden" / (test_name({GetParam(), 0}) + ".pfm"); }

  PassRegistry registry_;
  std::unique_ptr<Context> context_;
  std::unique_ptr<VulkanDevice> device_;
  std::unique_ptr<LoadedConfig> config_;
};

TEST_P(ConfigRender, DebugSwitchesGiveTheSameImage) {
  const Texels reference = render({});
  ASSERT_EQ(reference.width, kSize.width);
  const CompileOptions switches[] = {{.cull = false}, {.alias = false}, {.serialize = true}};
  for (const CompileOptions& o : switches) {
    EXPECT_TRUE(render(o).rgba == reference.rgba) << "cull " << o.cull << " alias " << o.alias << " serialize " << o.serialize;
  }
}

TEST_P(ConfigRender, MatchesItsGoldenImage) {
  const Texels t = render({});
  const Image rendered{t.width, t.height, t.rgba};
  if (std::getenv("VOLGRAPH_UPDATE_GOLDEN")) {
    write_image(golden_path().string(), rendered);
    GTEST_SKIP() << "wrote " << golden_path();
  }
  ASSERT_TRUE(fs::exists(golden_path())) << "no golden image: run with VOLGRAPH_UPDATE_GOLDEN=1 and look at " << golden_path();
  const Image golden = read_pfm(golden_path().string());
  ASSERT_EQ(golden.width, t.width);
  ASSERT_EQ(golden.height, t.height);
  const testing::ImageDifference d = testing::compare_images(t.rgba, golden.rgba);
  EXPECT_EQ(d.non_finite, 0u) << d.describe();
  EXPECT_LE(d.relative_mean_error, 0.01) << d.describe();
  EXPECT_LE(d.outlier_fraction, 0.005) << d.describe();
}

INSTANTIATE_TEST_SUITE_P(Shipped, ConfigRender, ::testing::ValuesIn(shipped_configs()), test_name);

}  // namespace
}  // namespace volgraph::vulkan
