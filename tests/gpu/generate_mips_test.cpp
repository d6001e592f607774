// generate_mips on both backends: a lit scene at an odd frame size (37 × 23, so every
// level but the last has an odd side) reduced to its full chain. Level 0 is the scene's
// colour bit for bit; each level k is the box mean of the texels of level k − 1 it covers
// (2 per axis, 3 along an odd side's last texel) within one fp16 step of the mean; the
// chain stops at the frame's full length (6 levels for 37 × 23) when more are asked.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

std::string mips_config(int levels) {
  return R"({ "output": { "size": [37, 23] },
  "scene": { "camera": { "position": [0, 1.5, 5], "target": [0, 0.5, 0] },
    "lights": [ { "name": "sun", "type": "directional", "direction": [0.4, -1, -0.3], "irradiance": [3, 3, 3] } ],
    "materials": { "red": { "albedo": [0.8, 0.1, 0.1] }, "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "shape": "sphere", "size": [1, 1, 1], "material": "red", "transform": { "translate": [0, 0.5, 0] } },
                 { "shape": "plane", "size": [10, 1, 10], "material": "grey" } ] },
  "graph": { "passes": [ { "name": "lit", "type": "scene" },
    { "name": "chain", "type": "generate_mips", "params": { "levels": )" + std::to_string(levels) + R"( }, "inputs": { "color": "lit.color" } } ],
    "outputs": ["chain.mips", "lit.color"] } })";
}

class GenerateMips : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  PassRegistry registry_;
};

// The box mean of the texels of `above` that texel (x, y) of a level w × h covers.
double box_mean(const Texels& above, uint32_t w, uint32_t h, uint32_t x, uint32_t y, size_t channel) {
  const auto covered = [](uint32_t t, uint32_t size_above, uint32_t size) {
    return (t == size - 1 && size_above > 2 * size) ? size_above - 2 * t : std::min(2u, size_above - 2 * t);
  };
  const uint32_t cx = covered(x, above.width, w), cy = covered(y, above.height, h);
  double sum = 0;
  for (uint32_t j = 0; j < cy; ++j) {
    for (uint32_t i = 0; i < cx; ++i) sum += above.rgba[4 * (size_t(2 * y + j) * above.width + 2 * x + i) + channel];
  }
  return sum / (cx * cy);
}

TEST_P(GenerateMips, EachLevelIsTheBoxMeanOfTheLevelAbove) {
  const LoadedConfig config = load_config_text("generate_mips.json", mips_config(14), registry_);
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const uint32_t chain = config.graph.outputs.at(0).resource;
  ASSERT_EQ(config.graph.resources[chain].desc.mip_levels, 6u) << "37 × 23's full chain: 37, 18, 9, 4, 2, 1";
  EXPECT_EQ(executor.read_output(0).rgba, executor.read_output(1).rgba) << "level 0 is the colour as it is";
  Texels above = executor.read_texture_level(chain, 0);
  double worst = 0;
  for (uint32_t level = 1; level < 6; ++level) {
    const Texels here = executor.read_texture_level(chain, level);
    ASSERT_EQ(here.width, std::max(1u, 37u >> level));
    ASSERT_EQ(here.height, std::max(1u, 23u >> level));
    for (uint32_t y = 0; y < here.height; ++y) {
      for (uint32_t x = 0; x < here.width; ++x) {
        for (size_t c = 0; c < 4; ++c) {
          const double want = box_mean(above, here.width, here.height, x, y, c);
          const double got = here.rgba[4 * (size_t(y) * here.width + x) + c];
          worst = std::max(worst, std::abs(got - want) / std::max(want, 1e-6));
          EXPECT_NEAR(got, want, fp16_steps(want)) << "level " << level << " texel " << x << ", " << y << " channel " << c;
        }
      }
    }
    above = here;
  }
  std::printf("generate_mips 37x23: every level within %.3g relative of the box mean of the level above\n", worst);
}

TEST_P(GenerateMips, TheChainHasTheLevelsAsked) {
  const LoadedConfig config = load_config_text("generate_mips.json", mips_config(3), registry_);
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  EXPECT_EQ(config.graph.resources[config.graph.outputs.at(0).resource].desc.mip_levels, 3u);
}

INSTANTIATE_TEST_SUITE_P(Backends, GenerateMips, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
