// atmosphere_transmittance_lut on both backends at its defaults (256 × 64 rgba32f, 32
// Gauss–Legendre panels), against the CPU twin in double (physics/atmosphere.h,
// physics/atmosphere_lut.h): every texel against physics::transmittance_to_top at the (r, mu)
// the texel holds, the largest absolute error below 1e-4 over the table (measured 8.3e-5, at
// grazing rays; 8 panels gave 1.2e-3, 16 3.5e-4) and 2e-5 over the zenith column (8.5e-6);
// e^(−τ) at the zenith from the ground equals the closed form of the profiles within 1e-4.
// Fixture: atmosphere_lut.h.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/atmosphere.h"
#include "physics/atmosphere_lut.h"
#include "tests/gpu/atmosphere_lut.h"

namespace volgraph::testing {
namespace {

class AtmosphereTransmittanceLut : public AtmosphereLutFixture {};

TEST_P(AtmosphereTransmittanceLut, TransmittanceMatchesTheDoubleTwinAndIsWithin1e4AtTheZenith) {
  const LoadedConfig config = load(R"("atmosphere": { "preset": "earth" })");
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const Texels lut = executor.read_output(0);
  ASSERT_EQ(lut.width, 256u);
  ASSERT_EQ(lut.height, 64u);
  const LutErrors e = transmittance_errors(lut, *config.config.scene.atmosphere);
  std::printf("transmittance LUT 256x64 against the double twin: largest absolute error %.3g over the table, %.3g at the zenith\n",
              e.all, e.zenith);
  EXPECT_LT(e.zenith, 2e-5);
  EXPECT_LT(e.all, 1e-4);
  // Texel (0, 0): r at the ground, mu = 1 — e^(−τ) of the profiles' closed form.
  const Vec3 tau = physics::zenith_optical_depth(*config.config.scene.atmosphere, 0);
  const physics::RadiusAndMu rm = physics::transmittance_lut_r_mu(*config.config.scene.atmosphere, {0.5 / 256, 0.5 / 64});
  ASSERT_NEAR(rm.mu, 1, 1e-12);
  ASSERT_NEAR(rm.r, config.config.scene.atmosphere->bottom_radius, 1e-6);
  for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(lut.rgba[c], std::exp(-tau[c]), 1e-4) << "channel " << c;
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereTransmittanceLut, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
