// The clouds' shadow on the atmosphere's light (cloud_shadow_map → atmosphere_aerial_perspective)
// on both backends: the air under a cloud layer, seen from the ground looking up toward it,
// in a volume `clouded` that reads the map and one `bare` that does not. Per texel the
// in-scattering's ratio clouded/bare equals the double twin's (physics::scattering_along
// with Ψ_ms exact and the sun's visibility exp(−τ) read from the pass's own map as
// include/cloud_shadow_lookup.glsl reads it, tests/gpu/cloud_shadow_twin.h): the LUTs'
// errors common to both volumes cancel in the ratio (within 5e-3; measured 1.4e-3). The transmittance is the air's alone
// (bit for bit as without the map), coverage 0 is the bare volume bit for bit.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/clouds/cloud_shadow_view.h"
#include "passes/passes.h"
#include "physics/atmosphere_multiscattering.h"
#include "physics/atmosphere_sky.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/cloud_shadow_twin.h"

namespace volgraph::testing {
namespace {

constexpr double kAirMapExtent = 40000;  // m: cloud_shadow_map's default extent
constexpr int kAirMapSize = 64;
constexpr int kAirVolume = 16;           // the volumes' columns per side and slices
constexpr double kAirDistance = 16000;   // m: how far the volumes reach

std::string air_under_clouds(const std::string& clouds) {
  const std::string luts = R"("transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering")";
  const std::string volume = R"("type": "atmosphere_aerial_perspective", "params": { "resolution": 16, "slices": 16, "distance": 16000 })";
  return R"({ "output": { "size": [16, 16] },
  "scene": { "camera": { "position": [0, 2, 0], "target": [0, 600, -1000], "fov_y_deg": 70 },
    "lights": [ { "name": "sun", "type": "directional", "direction": [0.3, -0.6, 0.5], "irradiance": [1, 1, 1] } ],
    "atmosphere": { "preset": "earth" },
    "clouds": { )" + clouds + R"( } },
  "graph": { "passes": [
    { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 32, "detail_size": 16, "curl_size": 32 } },
    { "name": "shadow", "type": "cloud_shadow_map", "params": { "size": 64 },
      "inputs": { "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } },
    { "name": "lut", "type": "atmosphere_transmittance_lut" },
    { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
    { "name": "clouded", )" + volume + R"(, "inputs": { )" + luts +
         R"(, "cloud_shadow": "shadow.optical_depth", "cloud_shadow_view": "shadow.view" } },
    { "name": "bare", )" + volume + R"(, "inputs": { )" + luts + R"( } } ],
    "outputs": ["clouded.aerial_scattering", "bare.aerial_scattering", "clouded.aerial_transmittance",
                "bare.aerial_transmittance", "shadow.optical_depth"] } })";
}

struct AirRun {
  Texels clouded, bare, clouded_transmittance, bare_transmittance, tau;
  Scene scene;
};

class AtmosphereAerialCloudShadow : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  AirRun run(const std::string& clouds) {
    const LoadedConfig config = load_config_text("atmosphere_aerial_cloud_shadow.json", air_under_clouds(clouds), registry_);
    AirRun r;
    r.scene = config.config.scene;
    Executor executor(device(), config.graph, &r.scene, {});
    executor.run_frame();
    r.clouded = executor.read_output(0), r.bare = executor.read_output(1);
    r.clouded_transmittance = executor.read_output(2), r.bare_transmittance = executor.read_output(3);
    r.tau = executor.read_output(4);
    return r;
  }
  PassRegistry registry_;
};

// The twin's in-scattering of texel (i, j, k), with the map's shadow or without.
Vec3 twin_in_scattering(const AirRun& r, int i, int j, int k, bool clouded) {
  const Atmosphere& a = *r.scene.atmosphere;
  const physics::AtmosphereView view = physics::atmosphere_view(r.scene);
  const physics::ViewRays rays = physics::view_rays(r.scene.camera, 1.0);
  const Vec3 d = physics::normalize(physics::view_ray(rays, (i + 0.5) / kAirVolume * 2 - 1, 1 - (j + 0.5) / kAirVolume * 2));
  const double mu = physics::dot(d, view.up), nu = physics::dot(d, view.toward_sun);
  const double length = std::min((k + 0.5) * kAirDistance / kAirVolume, physics::distance_to_boundary(a, view.r, mu));
  physics::SkySampling sampling;
  if (clouded) {
    const gpu::CloudShadowView map = cloud_shadow_view(r.scene, kAirMapExtent, kAirMapSize);
    sampling.sun_visibility = [map, d, &r](double t) {
      const auto [u, v] = cloud_shadow_map_uv(map, physics::add(r.scene.camera.position, physics::scaled(d, t)));
      if (u < 0 || u > 1 || v < 0 || v > 1) return 1.0;
      return std::exp(-cloud_shadow_tau_at(r.tau, u, v));
    };
  }
  const auto psi = [&](double radius, double mu_s) { return physics::multiscattering(a, radius, mu_s); };
  return physics::scattering_along(a, view.r, mu, view.mu_s, nu, length, psi, sampling).radiance;
}

TEST_P(AtmosphereAerialCloudShadow, TheAirUnderTheCloudsScattersTheSunThroughExpMinusTau) {
  const AirRun r = run(R"("bottom_altitude": 1500, "top_altitude": 3500, "coverage": 0.6, "extinction": 0.01,
                          "shape_scale": 6000, "wind": [0, 0, 0])");
  double worst = 0, darkest = 1;
  for (const auto [i, j, k] : {std::array{3, 4, 15}, std::array{8, 8, 15}, std::array{12, 2, 15}, std::array{5, 12, 9},
                               std::array{10, 6, 11}, std::array{1, 1, 15}, std::array{14, 13, 7}, std::array{7, 3, 13}}) {
    const Vec3 shadowed = twin_in_scattering(r, i, j, k, true), open = twin_in_scattering(r, i, j, k, false);
    const size_t at = 4 * ((size_t(k) * kAirVolume + j) * kAirVolume + i);
    for (size_t c = 0; c < 3; ++c) {
      const double want = shadowed[c] / open[c], got = r.clouded.rgba[at + c] / r.bare.rgba[at + c];
      darkest = std::min(darkest, want);
      worst = std::max(worst, std::abs(got - want));
    }
  }
  std::printf("aerial perspective under the clouds' shadow: ratio clouded/bare within %.3g of the twin's (darkest %.3f)\n", worst, darkest);
  ASSERT_LT(darkest, 0.8) << "some texel must lie in the clouds' shadow, so the check could fail";
  EXPECT_LT(worst, 5e-3);
}

TEST_P(AtmosphereAerialCloudShadow, TheShadowLeavesTheAirsTransmittanceAlone) {
  const AirRun r = run(R"("coverage": 0.6, "extinction": 0.01, "wind": [0, 0, 0])");
  EXPECT_EQ(r.clouded_transmittance.rgba, r.bare_transmittance.rgba);
  EXPECT_NE(r.clouded.rgba, r.bare.rgba);
}

TEST_P(AtmosphereAerialCloudShadow, CoverageZeroIsTheVolumeWithoutTheMapBitForBit) {
  const AirRun r = run(R"("coverage": 0)");
  EXPECT_EQ(r.clouded.rgba, r.bare.rgba);
}

INSTANTIATE_TEST_SUITE_P(Backends, AtmosphereAerialCloudShadow, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
