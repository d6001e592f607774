// Every shipped config (configs/*.json, configs/tests/*.json) renders on lavapipe, on
// each backend (Vulkan, WebGPU), with validation silent and:
// - the same image, bit for bit, under each of the plan's debug switches (--no-cull,
//   --no-alias, --serialize): culling and aliasing never change what is drawn;
// - no NaN or Inf in its output;
// - an image close to its golden image (tests/golden/): relative mean absolute error
//   ≤ 1 % and at most 0.5 % of pixels off by more than 5 % (tests/support/image_compare.h);
//   the same goldens hold for both backends, with the same metric.
// Goldens are rewritten (from Vulkan) with VOLGRAPH_UPDATE_GOLDEN=1; look at them before committing.
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/shipped_configs.h"
#include "tests/support/image_compare.h"
#include "tools/image_io.h"
#include "tests/support/source_dir.h"

namespace volgraph::testing {
namespace {

namespace fs = std::filesystem;
using ConfigOnBackend = std::tuple<std::string, Backend>;

std::string test_name(const ::testing::TestParamInfo<ConfigOnBackend>& info) {
  return config_test_name(std::get<0>(info.param)) + "_" + std::string(backend_name(std::get<1>(info.param)));
}

class ConfigRender : public OnEachBackend<ConfigOnBackend> {
 protected:
  Backend backend() const override { return std::get<1>(GetParam()); }
  const std::string& config() const { return std::get<0>(GetParam()); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
    Overrides o;
    o.size = kConfigTestSize;
    config_ = std::make_unique<LoadedConfig>(load_config(config_path(config()), registry_, o));
  }
  Texels render(const CompileOptions& options) {
    Executor executor(device(), config_->graph, &config_->config.scene, options);
    executor.run_frame();
    return executor.read_output(0);
  }
  fs::path golden_path() const { return fs::path(::volgraph::testing::source_dir()) / "tests/golden" / (config_test_name(config()) + ".pfm"); }

  PassRegistry registry_;
  std::unique_ptr<LoadedConfig> config_;
};

TEST_P(ConfigRender, DebugSwitchesGiveTheSameImage) {
  const Texels reference = render({});
  ASSERT_EQ(reference.width, kConfigTestSize.width);
  const CompileOptions switches[] = {{.cull = false}, {.alias = false}, {.serialize = true}};
  for (const CompileOptions& o : switches) {
    EXPECT_TRUE(render(o).rgba == reference.rgba) << "cull " << o.cull << " alias " << o.alias << " serialize " << o.serialize;
  }
}

TEST_P(ConfigRender, MatchesItsGoldenImage) {
  const Texels t = render({});
  const Image rendered{t.width, t.height, t.rgba};
  if (std::getenv("VOLGRAPH_UPDATE_GOLDEN") && backend() == Backend::vulkan) {
    write_image(golden_path().string(), rendered);
    GTEST_SKIP() << "wrote " << golden_path();
  }
  ASSERT_TRUE(fs::exists(golden_path())) << "no golden image: run with VOLGRAPH_UPDATE_GOLDEN=1 and look at " << golden_path();
  const Image golden = read_pfm(golden_path().string());
  ASSERT_EQ(golden.width, t.width);
  ASSERT_EQ(golden.height, t.height);
  const ImageDifference d = compare_images(t.rgba, golden.rgba);
  EXPECT_EQ(d.non_finite, 0u) << d.describe();
  EXPECT_LE(d.relative_mean_error, 0.01) << d.describe();
  EXPECT_LE(d.outlier_fraction, 0.005) << d.describe();
}

INSTANTIATE_TEST_SUITE_P(Shipped, ConfigRender,
                         ::testing::Combine(::testing::ValuesIn(shipped_configs()), ::testing::ValuesIn(gpu_backends())),
                         test_name);

}  // namespace
}  // namespace volgraph::testing
