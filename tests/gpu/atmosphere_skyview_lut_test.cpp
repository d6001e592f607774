// atmosphere_skyview_lut (Hillaire 2020 §5.3, 192 × 108 rgba16f) on both backends against its
// double twin (physics/atmosphere_sky.h): single scattering alone within 5e-3 of the table's
// largest value (measured 6.4e-4), with Ψ_ms within 1e-2 (2.1e-3). Fixture: atmosphere_lut.h.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/atmosphere_multiscattering.h"
#include "physics/atmosphere_sky.h"
#include "tests/gpu/atmosphere_lut.h"

namespace volgraph::testing {
namespace {

class AtmosphereSkyViewLut : public AtmosphereLutFixture {};

// The sky-view LUT against its double twin (physics/atmosphere_sky.h with the exact sun
// transmittance, and Ψ_ms exact where the pass reads the multiple-scattering LUT), every
// 9th texel: single scattering alone, then with Ψ_ms on a few texels (the twin's Ψ_ms is slow).
double sky_view_error(const Texels& lut, const Atmosphere& atmosphere, const physics::AtmosphereView& view, int stride,
                      const physics::MultiscatteringTerm& psi, double* largest) {
  const physics::SkyViewLutSize size{int(lut.width), int(lut.height)};
  double worst = 0;
  for (uint32_t j = 0; j < lut.height; j += stride) {
    for (uint32_t i = 0; i < lut.width; i += stride) {
      const physics::SkyViewDirection d =
          physics::sky_view_lut_direction(atmosphere, view.r, {(i + 0.5) / lut.width, (j + 0.5) / lut.height}, size);
      const double nu = physics::view_sun_cosine(d.mu, d.cos_azimuth, view.mu_s);
      const Vec3 want = physics::sky_scattering(atmosphere, view.r, d.mu, view.mu_s, nu, psi);
      for (size_t c = 0; c < 3; ++c) {
        const double got = lut.rgba[4 * (size_t(j) * lut.width + i) + c];
        EXPECT_TRUE(std::isfinite(got)) << "texel " << i << ", " << j;
        *largest = std::max(*largest, want[c]);
        worst = std::max(worst, std::abs(got - want[c]));
      }
    }
  }
  return worst;
}

TEST_P(AtmosphereSkyViewLut, SkyViewMatchesTheDoubleTwin) {
  const Atmosphere earth;
  {
    const LoadedConfig config = load_config_text("x.json", lut_config(R"("atmosphere": { "preset": "earth" })"), registry_,
                                                 {.sets = {"sky.multiscattering=false"}});
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    const physics::AtmosphereView view = physics::atmosphere_view(config.config.scene);
    ASSERT_NEAR(view.mu_s, std::sqrt(0.5), 1e-6);
    double largest = 0;
    const double worst = sky_view_error(executor.read_output(2), earth, view, 9, {}, &largest);
    std::printf("sky-view LUT 192x108, single scattering, against the double twin: %.3g of its largest value %.3g\n", worst / largest,
                largest);
    EXPECT_LT(worst, 5e-3 * largest);
  }
  const LoadedConfig config = load(R"("atmosphere": { "preset": "earth" })");
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const physics::AtmosphereView view = physics::atmosphere_view(config.config.scene);
  double largest = 0;
  const auto psi = [&](double r, double mu_s) { return physics::multiscattering(earth, r, mu_s); };
  const double worst = sky_view_error(executor.read_output(2), earth, view, 37, psi, &largest);
  std::printf("sky-view LUT with Ψ_ms against the double twin: %.3g of its largest value %.3g\n", worst / largest, largest);
  EXPECT_LT(worst, 1e-2 * largest);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereSkyViewLut, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
