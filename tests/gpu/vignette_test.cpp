// The pass author's guide's example pass (passes/post/vignette.cpp) against its closed
// form on both backends: a constant radiance L becomes L · mix(1, cos⁴θ, strength), θ the
// angle between the pixel's ray (DESIGN.md's pixel convention) and the optical axis.
// Bound: 1e-3 relative — the output is rgba16f (half a unit in the last place is 2^-11 ≈
// 4.9e-4 relative) and the shader computes cos²θ in 32-bit floats.
#include <cmath>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/support/source_dir.h"

namespace volgraph::testing {
namespace {

constexpr double kFovYDeg = 50;
constexpr uint32_t kVignetteWidth = 48, kVignetteHeight = 20;

double cos4_of_pixel(uint32_t i, uint32_t j) {
  const double tan_half = std::tan(kFovYDeg * M_PI / 360.0), aspect = double(kVignetteWidth) / double(kVignetteHeight);
  const double x = ((i + 0.5) / kVignetteWidth * 2 - 1) * tan_half * aspect, y = (1 - (j + 0.5) / kVignetteHeight * 2) * tan_half;
  const double cos2 = 1 / (1 + x * x + y * y);
  return cos2 * cos2;
}

class Vignette : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  Texels vignetted(double strength) {
    PassRegistry registry;
    register_builtin_passes(registry);
    Overrides o;
    o.size = Extent{kVignetteWidth, kVignetteHeight, 1};
    o.sets = {"lens.strength=" + std::to_string(strength)};
    LoadedConfig config = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/tests/vignette.json", registry, o);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }
};

TEST_P(Vignette, FullStrengthIsTheCos4Law) {
  const Texels t = vignetted(1);
  const double radiance[3] = {1.0, 0.5, 0.25};
  for (uint32_t j = 0; j < kVignetteHeight; ++j) {
    for (uint32_t i = 0; i < kVignetteWidth; ++i) {
      for (uint32_t c = 0; c < 3; ++c) {
        const double expected = radiance[c] * cos4_of_pixel(i, j);
        EXPECT_NEAR(t.rgba[4 * (j * kVignetteWidth + i) + c], expected, 1e-3 * expected) << "pixel " << i << ", " << j;
      }
    }
  }
  EXPECT_LT(t.rgba[0], 0.75) << "the corner must be visibly darker at a 50° view";  // cos⁴ ≈ 0.56 there
}

TEST_P(Vignette, ZeroStrengthLeavesTheColourExactly) {
  const Texels t = vignetted(0);
  for (size_t p = 0; p < size_t(kVignetteWidth) * kVignetteHeight; ++p) {
    EXPECT_EQ(t.rgba[4 * p], 1.0f);
    EXPECT_EQ(t.rgba[4 * p + 1], 0.5f);
    EXPECT_EQ(t.rgba[4 * p + 2], 0.25f);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, Vignette, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
