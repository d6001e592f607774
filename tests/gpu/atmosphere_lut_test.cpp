// The atmosphere's lookup tables on both backends, against the CPU twin in double
// (physics/atmosphere.h, physics/atmosphere_lut.h):
// - atmosphere_transmittance_lut at its defaults (256 × 64 rgba32f, 32 Gauss–Legendre
//   panels): every texel against physics::transmittance_to_top at the (r, mu) the texel
//   holds, the largest absolute error below 1e-4 over the table (measured 8.3e-5, at grazing
//   rays; 8 panels gave 1.2e-3, 16 3.5e-4) and 2e-5 over the zenith column (8.5e-6); e^(−τ)
//   at the zenith from the ground equals the closed form of the profiles within 1e-4;
// - atmosphere_multiscattering_lut (Hillaire 2020 §5.5, 32 × 32 rgba16f, 8² directions,
//   20 steps) against its double twin (physics/atmosphere_multiscattering.h, the sun's
//   transmittance exact where the pass reads the LUT): every third texel within 5e-3 of the
//   table's largest value (measured 7.1e-4: the LUT's bilinear lookup, float, fp16);
// - atmosphere_skyview_lut (Hillaire 2020 §5.3, 192 × 108 rgba16f) against its double twin
//   (physics/atmosphere_sky.h): single scattering alone within 5e-3 of the table's largest
//   value (measured 6.4e-4), with Ψ_ms within 1e-2 (2.1e-3);
// - atmosphere_aerial_perspective (Hillaire 2020 §5.4, 32 × 32 × 32 over 32 km) on four
//   texels against its double twin: below;
// - cached: a second frame with the same atmosphere runs no LUT pass, a changed atmosphere
//   runs them again, a camera that climbs reruns the sky view alone;
// - no atmosphere in the scene: the pass is culled.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_lut.h"
#include "physics/atmosphere_multiscattering.h"
#include "physics/atmosphere_sky.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

std::string lut_config(const std::string& atmosphere) {
  return R"({ "output": { "size": [16, 16] },
  "scene": { "camera": { "position": [0, 1, 5], "target": [0, 1, 0] },
             "lights": [ { "name": "sun", "type": "directional", "direction": [0, -1, -1], "irradiance": [1, 1, 1] } ],
             )" + atmosphere + R"( },
  "graph": { "passes": [ { "name": "lut", "type": "atmosphere_transmittance_lut" },
                         { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
                         { "name": "sky", "type": "atmosphere_skyview_lut",
                           "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
                         { "name": "air", "type": "atmosphere_aerial_perspective",
                           "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } } ],
             "outputs": ["lut.transmittance", "ms.multiscattering", "sky.sky_view", "air.aerial_scattering", "air.aerial_transmittance"] } })";
}

class AtmosphereLut : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const std::string& atmosphere) { return load_config_text("atmosphere_lut.json", lut_config(atmosphere), registry_); }
  PassRegistry registry_;
};

// The largest absolute error of each texel against the double-precision twin, over the
// whole table and over the zenith (mu = 1: the first column) alone.
struct LutErrors {
  double all = 0, zenith = 0;
};

LutErrors transmittance_errors(const Texels& lut, const Atmosphere& atmosphere) {
  LutErrors e;
  const physics::TransmittanceLutSize size{int(lut.width), int(lut.height)};
  for (uint32_t j = 0; j < lut.height; ++j) {
    for (uint32_t i = 0; i < lut.width; ++i) {
      const physics::LutUv uv{(i + 0.5) / lut.width, (j + 0.5) / lut.height};
      const physics::RadiusAndMu rm = physics::transmittance_lut_r_mu(atmosphere, uv, size);
      const Vec3 want = physics::transmittance_to_top(atmosphere, rm.r, rm.mu);
      for (size_t c = 0; c < 3; ++c) {
        const double error = std::abs(lut.rgba[4 * (size_t(j) * lut.width + i) + c] - want[c]);
        e.all = std::max(e.all, error);
        if (i == 0) e.zenith = std::max(e.zenith, error);  // x_mu = 0: the distance to the top at its least, mu = 1
      }
    }
  }
  return e;
}

TEST_P(AtmosphereLut, TransmittanceMatchesTheDoubleTwinAndIsWithin1e4AtTheZenith) {
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

TEST_P(AtmosphereLut, AnUnchangedAtmosphereRunsNoLutPassAChangedOneRunsItAgain) {
  LoadedConfig config = load(R"("atmosphere": { "preset": "earth" })");
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  ASSERT_EQ(executor.timings().size(), 4u);
  for (const PassTiming& t : executor.timings()) EXPECT_FALSE(t.cached) << t.pass << ": the first frame fills the tables";
  executor.run_frame();
  for (const PassTiming& t : executor.timings()) EXPECT_TRUE(t.cached) << t.pass << ": an unchanged atmosphere keeps last frame's table";
  config.config.scene.atmosphere->mie_extinction = {8e-6, 8e-6, 8e-6};
  executor.run_frame();
  for (const PassTiming& t : executor.timings()) EXPECT_FALSE(t.cached) << t.pass << ": a changed atmosphere fills it again";
  config.config.scene.camera.position[1] += 1000;
  executor.run_frame();
  for (const PassTiming& t : executor.timings()) {
    EXPECT_EQ(t.cached, t.pass != "sky" && t.pass != "air") << t.pass << ": a camera 1 km higher changes the sky view and the aerial perspective alone";
  }
  const LutErrors e = transmittance_errors(executor.read_output(0), *config.config.scene.atmosphere);
  EXPECT_LT(e.zenith, 1e-4) << "the table is the changed atmosphere's";
}

TEST_P(AtmosphereLut, NoAtmosphereNoLutPass) {
  const LoadedConfig config = load(R"("background": { "radiance": [0, 0, 0] })");
  const Plan plan = compile_loaded(config);
  EXPECT_TRUE(plan.order.empty());
  EXPECT_EQ(plan.culled.size(), 4u);
}

// Ψ_ms against its double twin (the same method with the exact sun transmittance): what
// is left is the transmittance LUT's bilinear lookup, the float maths and fp16 storage.
TEST_P(AtmosphereLut, MultiscatteringMatchesTheDoubleTwin) {
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

TEST_P(AtmosphereLut, SkyViewMatchesTheDoubleTwin) {
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

// The aerial-perspective volume against its double twin (physics::scattering_along with
// Ψ_ms exact, 40 midpoint samples) on four texels: each column's ray through the frame,
// slice k to (k + ½) km. In-scattering within 3e-2 relative (measured 1.9e-2: the pass
// reads Ψ_ms and the sun's transmittance from their LUTs, the twin computes them; fp16),
// transmittance within 2e-3 absolute (4.6e-4).
TEST_P(AtmosphereLut, AerialPerspectiveMatchesTheDoubleTwin) {
  const LoadedConfig config = load(R"("atmosphere": { "preset": "earth" })");
  Executor executor(device(), config.graph, &config.config.scene, {});
  executor.run_frame();
  const Texels scattering = executor.read_output(3), transmittance = executor.read_output(4);
  ASSERT_EQ(scattering.width, 32u);
  ASSERT_EQ(scattering.depth, 32u);
  const Scene& scene = config.config.scene;
  const Atmosphere& a = *scene.atmosphere;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  const physics::ViewRays rays = physics::view_rays(scene.camera, 1.0);  // the frame is 16x16
  const auto psi = [&](double r, double mu_s) { return physics::multiscattering(a, r, mu_s); };
  double worst_scattering = 0, worst_transmittance = 0, largest = 0;
  for (const auto [i, j, k] : {std::array{5, 7, 0}, std::array{16, 16, 3}, std::array{30, 2, 31}, std::array{2, 29, 12}}) {
    const Vec3 d = physics::normalize(physics::view_ray(rays, (i + 0.5) / 32 * 2 - 1, 1 - (j + 0.5) / 32 * 2));
    const double mu = physics::dot(d, view.up), nu = physics::dot(d, view.toward_sun);
    const double length = std::min((k + 0.5) * 1000, physics::distance_to_boundary(a, view.r, mu));
    const physics::ScatteringAlong want = physics::scattering_along(a, view.r, mu, view.mu_s, nu, length, psi);
    const size_t at = 4 * ((size_t(k) * 32 + j) * 32 + i);
    for (size_t c = 0; c < 3; ++c) {
      largest = std::max(largest, want.radiance[c]);
      worst_scattering = std::max(worst_scattering, std::abs(scattering.rgba[at + c] - want.radiance[c]) / want.radiance[c]);
      worst_transmittance = std::max(worst_transmittance, std::abs(transmittance.rgba[at + c] - want.transmittance[c]));
    }
  }
  std::printf("aerial perspective 32x32x32 against the double twin: in-scattering %.3g relative, transmittance %.3g absolute\n",
              worst_scattering, worst_transmittance);
  EXPECT_LT(worst_scattering, 3e-2);
  EXPECT_LT(worst_transmittance, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereLut, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
