// cloud_aerial_perspective (passes/clouds/cloud_aerial_perspective.cpp) on both backends:
// - every pixel equals its CPU twin: cloud_march's radiance L and transmittance T_c read
//   back, the aerial-perspective volumes read back and interpolated at the pixel's column
//   and cloud_march's distance (physics::aerial_perspective_slice, as aerial_perspective_apply's
//   test does), L·T_air + S_air·E·(1 − T_c), within two fp16 steps; pixels without cloud
//   (T_c = 1) pass bit for bit; the transmittance is never changed;
// - the clouds' depth (cloud_march.distance) puts the opacity-weighted mean sample inside
//   the layer; the air turns nearly opaque clouds bluer.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere_lut.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kSide = 16;             // the frame and the volume's columns: each pixel centre a column's centre
constexpr int kSlices = 16;                // over kVolumeDistance
constexpr double kVolumeDistance = 32e3;   // m
constexpr double kBottom = 1500, kTop = 4000;  // the layer's altitudes (m)
constexpr double kEarthPresetRadius = 6360e3;   // the earth preset's bottom radius (m)

// Cumulus seen from the ground 15° up, through the earth's air; outputs the clouds through
// the air, the march's clouds and distance, and the two volumes.
std::string config_text() {
  return R"({ "output": { "size": [16, 16] },
  "scene": { "camera": { "position": [0, 2, 0], "target": [0, 2.268, -1], "fov_y_deg": 40, "far": 100000 },
    "lights": [ { "name": "sun", "type": "directional", "direction": [0.3, -0.5, -0.8], "irradiance": [3, 3, 3] } ],
    "clouds": { "bottom_altitude": 1500, "top_altitude": 4000, "coverage": 0.6, "extinction": 0.06,
                "shape_scale": 12000, "detail_scale": 1500 },
    "atmosphere": { "preset": "earth" } },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 32, "detail_size": 16, "curl_size": 32 } },
      { "name": "march", "type": "cloud_march", "params": { "steps": 32, "light_steps": 4 },
        "inputs": { "depth": "lit.depth", "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl" } },
      { "name": "lut", "type": "atmosphere_transmittance_lut" },
      { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
      { "name": "aerial", "type": "atmosphere_aerial_perspective", "params": { "resolution": 16, "slices": 16, "distance": 32000 },
        "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
      { "name": "air", "type": "cloud_aerial_perspective",
        "inputs": { "clouds": "march.clouds", "distance": "march.distance", "lookup": "aerial.lookup",
                    "aerial_scattering": "aerial.aerial_scattering", "aerial_transmittance": "aerial.aerial_transmittance" } } ],
    "outputs": ["air.through_air", "march.clouds", "march.distance", "aerial.aerial_scattering", "aerial.aerial_transmittance"] } })";
}

struct Frames {
  Texels through_air, clouds, distance, scattering, transmittance;
  Vec3 sun{0, 0, 0};
  Camera camera;
};

class CloudAerialPerspective : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  Frames run() {
    const LoadedConfig config = load_config_text("cloud_aerial_perspective.json", config_text(), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    return {executor.read_output(0), executor.read_output(1), executor.read_output(2), executor.read_output(3), executor.read_output(4),
            config.config.scene.lights[0].irradiance, config.config.scene.camera};
  }
  PassRegistry registry_;
};

// The twin at pixel (i, j): the column's texels interpolated along the slices at distance t.
Vec3 expected_pixel(const Frames& f, uint32_t i, uint32_t j) {
  const size_t p = 4 * (size_t(j) * kSide + i);
  const double t = f.distance.rgba[p], cloud_t = f.clouds.rgba[p + 3];
  const physics::AerialSlice slice = physics::aerial_perspective_slice(t, kVolumeDistance, kSlices);
  const double z = slice.w * kSlices - 0.5;
  const uint32_t k0 = uint32_t(std::floor(z)), k1 = std::min(k0 + 1, uint32_t(kSlices - 1));
  const double w = z - k0;
  Vec3 e{0, 0, 0};
  for (size_t c = 0; c < 3; ++c) {
    const auto at = [&](const Texels& v, uint32_t k) { return double(v.rgba[4 * ((k * kSide + j) * kSide + i) + c]); };
    const double s = (1 - w) * at(f.scattering, k0) + w * at(f.scattering, k1);
    const double tr = 1 - (1 - ((1 - w) * at(f.transmittance, k0) + w * at(f.transmittance, k1))) * slice.ramp;
    e[c] = f.clouds.rgba[p + c] * tr + s * f.sun[c] * slice.ramp * (1 - cloud_t);
  }
  return e;
}

TEST_P(CloudAerialPerspective, EveryPixelIsItsTwinAndClearSkyPassesUnchanged) {
  const Frames f = run();
  ASSERT_EQ(f.through_air.width, kSide);
  ASSERT_EQ(f.scattering.width, kSide);
  int cloudy = 0;
  for (uint32_t j = 0; j < kSide; ++j) {
    for (uint32_t i = 0; i < kSide; ++i) {
      const size_t p = 4 * (size_t(j) * kSide + i);
      ASSERT_EQ(f.through_air.rgba[p + 3], f.clouds.rgba[p + 3]) << "the transmittance is the march's, pixel " << i << "," << j;
      if (f.clouds.rgba[p + 3] >= 1.0f) {
        for (size_t c = 0; c < 3; ++c) ASSERT_EQ(f.through_air.rgba[p + c], f.clouds.rgba[p + c]) << "clear pixel " << i << "," << j;
        continue;
      }
      ++cloudy;
      const Vec3 e = expected_pixel(f, i, j);
      for (size_t c = 0; c < 3; ++c) {
        EXPECT_NEAR(f.through_air.rgba[p + c], e[c], fp16_steps(e[c]) + 1e-5) << "pixel " << i << "," << j << " channel " << c;
      }
    }
  }
  EXPECT_GT(cloudy, int(kSide * kSide) / 8) << "the frame must show clouds";
}

// The opacity-weighted mean of the march's samples lies on the view ray inside the layer.
TEST_P(CloudAerialPerspective, TheCloudsDepthLiesInsideTheLayer) {
  const Frames f = run();
  for (uint32_t j = 0; j < kSide; ++j) {
    for (uint32_t i = 0; i < kSide; ++i) {
      const size_t p = 4 * (size_t(j) * kSide + i);
      if (f.clouds.rgba[p + 3] >= 1.0f) continue;
      const Vec3 d = physics::pixel_ray(f.camera, kSide, kSide, i, j);
      const double t = f.distance.rgba[p];
      const Vec3 q{f.camera.position[0] + t * d[0], f.camera.position[1] + kEarthPresetRadius + t * d[1], f.camera.position[2] + t * d[2]};
      const double altitude = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) - kEarthPresetRadius;
      EXPECT_GE(altitude, kBottom - 20) << "pixel " << i << "," << j << " at " << t << " m";
      EXPECT_LE(altitude, kTop + 20) << "pixel " << i << "," << j << " at " << t << " m";
    }
  }
}

// Kilometres of air between the camera and nearly opaque clouds turn every such pixel
// bluer: Rayleigh's λ⁻⁴ takes more blue than red and adds more blue than red.
TEST_P(CloudAerialPerspective, TheAirTurnsOpaqueCloudsBluer) {
  const Frames f = run();
  int opaque = 0;
  for (uint32_t p = 0; p < kSide * kSide; ++p) {
    const float* cloud = &f.clouds.rgba[4 * p];
    const float* seen = &f.through_air.rgba[4 * p];
    if (cloud[3] > 0.1f || cloud[0] <= 0.0f) continue;
    ++opaque;
    EXPECT_GT(seen[2] / seen[0], cloud[2] / cloud[0]) << "pixel " << p << ": the air's blue";
  }
  EXPECT_GT(opaque, 0) << "the frame must show nearly opaque clouds";
}

INSTANTIATE_TEST_SUITE_P(Backends, CloudAerialPerspective, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
