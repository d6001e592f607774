// The sky pass on both backends: a scene with no surface under the earth's atmosphere, the
// camera 2 m up looking at the horizon, the sun 20° up ahead of it. Against the double twin
// (physics/atmosphere_sky.h) per pixel, single scattering alone (the sky-view LUT's
// multiple-scattering term off): the LUT's interpolation, float and fp16 are what is left
// — relative error over the pixels 1° and more above the horizon, mean below 1e-2 and
// largest below 3e-2 (measured 8.6e-4 and 6.0e-3); the sun's disk at its centre is
// E / (π sin²α) × the transmittance toward it (plus the sky); with scattering off the sky is
// black and the disk (0.05 rad, so that pixel centres fall in it) is the sun's radiance
// times the transmittance, within fp16.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "physics/camera.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kAtmosphereSkyWidth = 64, kAtmosphereSkyHeight = 36;

std::string sky_config(const std::string& atmosphere) {
  return R"({ "output": { "size": [64, 36] },
  "scene": { "camera": { "position": [0, 2, 0], "target": [0, 2.2, -1], "fov_y_deg": 60 },
             "lights": [ { "name": "sun", "type": "directional", "direction": [0, -0.3420201, 0.9396926], "irradiance": [2, 2, 2] } ],
             "atmosphere": )" + atmosphere + R"( },
  "graph": { "passes": [
    { "name": "lut", "type": "atmosphere_transmittance_lut" },
    { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
    { "name": "sky_view", "type": "atmosphere_skyview_lut", "params": { "multiscattering": false },
      "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
    { "name": "lit", "type": "scene" },
    { "name": "sky", "type": "sky", "inputs": { "color": "lit.color", "depth": "lit.depth", "transmittance": "lut.transmittance",
                                                "sky_view": "sky_view.sky_view" } } ],
    "outputs": ["sky.color"] } })";
}

class Sky : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  Texels render(const LoadedConfig& config) {
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
};

Vec3 pixel_direction(const Camera& camera, uint32_t i, uint32_t j) {
  const physics::ViewRays rays = physics::view_rays(camera, double(kAtmosphereSkyWidth) / kAtmosphereSkyHeight);
  return physics::normalize(physics::view_ray(rays, (i + 0.5) / kAtmosphereSkyWidth * 2 - 1, 1 - (j + 0.5) / kAtmosphereSkyHeight * 2));
}

TEST_P(Sky, SingleScatteringMatchesTheDoubleTwinThroughTheLut) {
  const LoadedConfig config = load_config_text("sky.json", sky_config(R"({ "preset": "earth" })"), registry_);
  const Texels image = render(config);
  const Scene& scene = config.config.scene;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  const Atmosphere& a = *scene.atmosphere;
  double worst = 0, sum_error = 0, sum = 0;
  for (uint32_t j = 0; j < kAtmosphereSkyHeight; ++j) {
    for (uint32_t i = 0; i < kAtmosphereSkyWidth; ++i) {
      const Vec3 d = pixel_direction(scene.camera, i, j);
      const physics::SkyViewDirection sd = physics::sky_view_direction(view, d);
      if (sd.mu < 0.02) continue;  // the horizon's few pixels: compared apart below
      const Vec3 sky = physics::sky_scattering(a, view.r, sd.mu, view.mu_s, physics::view_sun_cosine(sd.mu, sd.cos_azimuth, view.mu_s));
      const Vec3 disk = physics::sun_disk_radiance(a, view, d);
      for (size_t c = 0; c < 3; ++c) {
        const double want = 2 * (sky[c] + disk[c]);
        const double got = image.rgba[4 * (size_t(j) * kAtmosphereSkyWidth + i) + c];
        ASSERT_TRUE(std::isfinite(got));
        worst = std::max(worst, std::abs(got - want) / want);
        sum_error += std::abs(got - want);
        sum += want;
      }
    }
  }
  std::printf("sky pass, single scattering, 64x36, against the double twin: relative mean error %.3g, largest %.3g\n", sum_error / sum,
              worst);
  EXPECT_LT(sum_error / sum, 1e-2);
  EXPECT_LT(worst, 3e-2);
}

TEST_P(Sky, WithoutScatteringTheSkyIsBlackAndTheSunIsItsRadianceThroughTheAir) {
  const LoadedConfig config = load_config_text(
      "sky.json", sky_config(R"({ "preset": "earth", "rayleigh_scattering": [0, 0, 0], "mie_scattering": [0, 0, 0], "ground_albedo": [0, 0, 0],
                                  "sun": { "angular_radius": 0.05 } })"),
      registry_);
  const Texels image = render(config);
  const Scene& scene = config.config.scene;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  int disk_pixels = 0;
  for (uint32_t j = 0; j < kAtmosphereSkyHeight; ++j) {
    for (uint32_t i = 0; i < kAtmosphereSkyWidth; ++i) {
      const Vec3 disk = physics::sun_disk_radiance(*scene.atmosphere, view, pixel_direction(scene.camera, i, j));
      disk_pixels += disk[0] > 0;
      for (size_t c = 0; c < 3; ++c) {
        const double got = image.rgba[4 * (size_t(j) * kAtmosphereSkyWidth + i) + c];
        EXPECT_NEAR(got, 2 * disk[c], 2e-3 * 2 * disk[c] + 1e-7) << "pixel " << i << ", " << j;
      }
    }
  }
  std::printf("sun disk pixels at 64x36: %d\n", disk_pixels);
  EXPECT_GE(disk_pixels, 4) << "a 0.05 rad sun covers a few pixels of 1.7°";
}

INSTANTIATE_TEST_SUITE_P(Backends, Sky, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
