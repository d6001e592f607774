// atmosphere_multiscattering_lut (Hillaire 2020 §5.5, 32 × 32 rgba16f, 8² directions, 20
// steps) on both backends against its double twin (physics/atmosphere_multiscattering.h, the
// sun's transmittance exact where the pass reads the LUT): every third texel within 5e-3 of
// the table's largest value (measured 7.1e-4: the LUT's bilinear lookup, float, fp16).
// Fixture: atmosphere_lut.h.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/atmosphere_lut.h"
#include "physics/atmosphere_multiscattering.h"
#include "tests/gpu/atmosphere_lut.h"

namespace volgraph::testing {
namespace {

class AtmosphereMultiscatteringLut : public AtmosphereLutFixture {};

// Ψ_ms against its double twin (the same method with the exact sun transmittance): what
// is left is the transmittance LUT's bilinear lookup, the float maths and fp16 storage.
TEST_P(AtmosphereMultiscatteringLut, MultiscatteringMatchesTheDoubleTwin) {
  const LoadedConfig config = load(R"("atmosphere": { "preset": "earth" })");
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const Texels lut = executor.read_output(1);
  ASSERT_EQ(lut.width, 32u);
  ASSERT_EQ(lut.height, 32u);
  const Atmosphere& atmosphere = *config.config.scene.atmosphere;
  double worst = 0, largest = 0;
  for (uint32_t j = 0; j < lut.height; j += 3) {
    for (uint32_t i = 0; i < lut.width; i += 3) {
      const physics::RadiusAndMuS rm = physics::multiscattering_lut_r_mu_s(atmosphere, {(i + 0.5) / 32, (j + 0.5) / 32});
      const Vec3 want = physics::multiscattering(atmosphere, rm.r, rm.mu_s);
      for (size_t c = 0; c < 3; ++c) {
        const double got = lut.rgba[4 * (size_t(j) * lut.width + i) + c];
        ASSERT_TRUE(std::isfinite(got)) << "texel " << i << ", " << j;
        largest = std::max(largest, want[c]);
        worst = std::max(worst, std::abs(got - want[c]));
      }
    }
  }
  std::printf("multiscattering LUT 32x32 against the double twin: largest absolute error %.3g, %.3g of its largest value %.3g\n", worst,
              worst / largest, largest);
  EXPECT_GT(largest, 0);
  EXPECT_LT(worst, 5e-3 * largest);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereMultiscatteringLut, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
