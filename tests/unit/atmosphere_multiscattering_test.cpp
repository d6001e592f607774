// Hillaire 2020's multiple-scattering term Ψ_ms (physics/atmosphere_multiscattering.h) on
// the earth preset: what the method guarantees.
#include <gtest/gtest.h>

#include "physics/atmosphere.h"
#include "physics/atmosphere_multiscattering.h"

namespace volgraph::physics {
namespace {

constexpr double kGround = 6360e3;

TEST(AtmosphereMultiscattering, TheTransferIsAFractionAndTheTermIsPositive) {
  const Atmosphere earth;
  for (double altitude : {0.0, 1e3, 10e3, 59e3}) {
    for (double mu_s : {1.0, 0.5, 0.0, -0.2}) {
      const MultiscatteringTerms t = multiscattering_terms(earth, kGround + altitude, mu_s);
      const Vec3 psi = multiscattering(earth, kGround + altitude, mu_s);
      for (size_t c = 0; c < 3; ++c) {
        EXPECT_GT(t.transfer[c], 0) << altitude << " m, mu_s " << mu_s;
        EXPECT_LT(t.transfer[c], 1) << "each order loses energy";
        EXPECT_GE(psi[c], t.second_order[c]) << "Ψ adds the orders past the second";
        EXPECT_TRUE(std::isfinite(psi[c]));
      }
    }
  }
}

TEST(AtmosphereMultiscattering, NothingScattersWithoutScattering) {
  Atmosphere dark;
  dark.rayleigh_scattering = {0, 0, 0};
  dark.mie_scattering = {0, 0, 0};
  dark.ground_albedo = {0, 0, 0};
  const Vec3 psi = multiscattering(dark, kGround + 1e3, 0.7);
  for (size_t c = 0; c < 3; ++c) EXPECT_EQ(psi[c], 0);
}

TEST(AtmosphereMultiscattering, ABrighterGroundAddsLightAndTheSunBelowTheHorizonLeavesLess) {
  Atmosphere black_ground;
  black_ground.ground_albedo = {0, 0, 0};
  const Atmosphere earth;
  const Vec3 noon = multiscattering(earth, kGround + 500, 1.0), dark_noon = multiscattering(black_ground, kGround + 500, 1.0);
  const Vec3 night = multiscattering(earth, kGround + 500, -0.5);
  for (size_t c = 0; c < 3; ++c) {
    EXPECT_GT(noon[c], dark_noon[c]) << "the ground's bounce";
    EXPECT_LT(night[c], 1e-3 * noon[c]) << "a sun 30° below the horizon lights almost nothing";
  }
}

}  // namespace
}  // namespace volgraph::physics
