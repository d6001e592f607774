// sky_cube on both backends: the cube's faces hold the sky pass's own image in their
// directions (one GLSL text, include/atmosphere_sky_toward.glsl; the cube's directions
// from include/cube_face.h, whose C++ twin the test checks against the camera's pixel
// rays), every face against the sky's double twin, and the stress cases (a 1-texel face,
// a camera in space, the sun below the horizon): every texel finite. The graph's
// texture_cube kind is exercised whole: a storage write through the faces' 2D-array view,
// the barriers of six layers, the read-back face after face.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "physics/camera.h"
#include "physics/cube_face.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/config_on_each_backend.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kSkyCubeFace = 16;

struct SkyCubeCase {
  double altitude = 2;
  double sun_elevation = 0.35;  // rad, toward −z
  uint32_t face = kSkyCubeFace;
  std::string cube_params = "{}";  // "{}": the size only
  std::string lut_params = "{}";   // the sky-view LUT's
};

std::string sky_cube_number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// The camera looks along −z with a 90° square view: its pixels' rays are face −z's texel
// directions, mirrored left to right (a cube's faces are seen from outside).
std::string sky_cube_config(const SkyCubeCase& k) {
  const std::string y = sky_cube_number(k.altitude);
  const std::string sun = "[0, " + sky_cube_number(-std::sin(k.sun_elevation)) + ", " + sky_cube_number(std::cos(k.sun_elevation)) + "]";
  return R"({ "output": { "size": [)" + std::to_string(k.face) + ", " + std::to_string(k.face) + R"(] },
  "scene": { "camera": { "position": [0, )" + y + R"(, 0], "target": [0, )" + y + R"(, -1], "fov_y_deg": 90 },
             "lights": [ { "name": "sun", "type": "directional", "direction": )" + sun + R"(, "irradiance": [2, 2, 2] } ],
             "atmosphere": { "preset": "earth" } },
  "graph": { "passes": [
    { "name": "lut", "type": "atmosphere_transmittance_lut" },
    { "name": "ms", "type": "atmosphere_multiscattering_lut", "inputs": { "transmittance": "lut.transmittance" } },
    { "name": "sky_view", "type": "atmosphere_skyview_lut", "params": )" + k.lut_params + R"(, "inputs": { "transmittance": "lut.transmittance", "multiscattering": "ms.multiscattering" } },
    { "name": "lit", "type": "scene" },
    { "name": "sky", "type": "sky", "params": { "sun_disk": false },
      "inputs": { "color": "lit.color", "depth": "lit.depth", "transmittance": "lut.transmittance", "sky_view": "sky_view.sky_view", "multiscattering": "ms.multiscattering" } },
    { "name": "env", "type": "sky_cube", "params": )" + (k.cube_params == "{}" ? R"({ "size": )" + std::to_string(k.face) + " }" : k.cube_params) + R"(,
      "inputs": { "transmittance": "lut.transmittance", "sky_view": "sky_view.sky_view", "multiscattering": "ms.multiscattering" } } ],
    "outputs": ["sky.color", "env.cube"] } })";
}

class SkyCube : public ConfigOnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  // The sky pass's image and the cube (six slices, face after face) after one frame; scene_ the case's scene.
  std::pair<Texels, Texels> render(const SkyCubeCase& k) {
    std::vector<Texels> out = render_outputs("sky_cube.json", sky_cube_config(k), 2);
    return {std::move(out[0]), std::move(out[1])};
  }
};

Vec3 cube_texel(const Texels& cube, int face, uint32_t i, uint32_t j) {
  const size_t at = 4 * ((size_t(face) * cube.height + j) * cube.width + i);
  return {cube.rgba[at], cube.rgba[at + 1], cube.rgba[at + 2]};
}

Vec3 image_texel(const Texels& image, uint32_t i, uint32_t j) {
  const size_t at = 4 * (size_t(j) * image.width + i);
  return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2]};
}

TEST_P(SkyCube, HasSixSquareFacesOfItsSize) {
  const auto [sky, cube] = render({});
  EXPECT_EQ(cube.width, kSkyCubeFace);
  EXPECT_EQ(cube.height, kSkyCubeFace);
  EXPECT_EQ(cube.depth, 6u);
  EXPECT_TRUE(all_finite(cube));
}

// Face −z (5) texel (n − 1 − i, j) looks where the 90° camera's pixel (i, j) looks (the
// twins say so to 1e-6), and holds what the sky pass drew there: the same LUT texels read
// through the same function, the directions made two ways (measured on lavapipe, both
// backends: equal, largest relative difference 0; bound: one fp16 step).
TEST_P(SkyCube, FaceMinusZHoldsTheSkyPassImageMirrored) {
  const SkyCubeCase k;
  const auto [sky, cube] = render(k);
  const physics::ViewRays rays = physics::view_rays(scene_.camera, 1.0);
  double largest = 0;
  for (uint32_t j = 0; j < k.face; ++j) {
    for (uint32_t i = 0; i < k.face; ++i) {
      const Vec3 pixel = physics::normalize(physics::view_ray(rays, (i + 0.5) / k.face * 2 - 1, 1 - (j + 0.5) / k.face * 2));
      const glm::vec3 texel = physics::cube::cube_texel_direction(5, glm::ivec2(int(k.face - 1 - i), int(j)), int(k.face));
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(pixel[size_t(c)], texel[c], 1e-6) << "pixel " << i << ", " << j;
      const Vec3 want = image_texel(sky, i, j), got = cube_texel(cube, 5, k.face - 1 - i, j);
      for (size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(got[c] - want[c]) / std::max(want[c], 1e-6));
    }
  }
  std::printf("face -z against the sky pass: largest relative difference %.3g\n", largest);
  EXPECT_LT(largest, 2e-3);
}

// Every face against the sky's double twin in its texels' directions (the single-scattering
// integral the LUT holds plus the ground; Ψ_ms off in the LUT and the cube, as the twin),
// away from the horizon where the LUT's texels blend both sides: relative mean error, the
// sky pass's own bound against the same twin (atmosphere_sky_view_test.cpp).
TEST_P(SkyCube, EveryFaceMatchesTheSkyTwinAwayFromTheHorizon) {
  SkyCubeCase k;
  k.cube_params = R"({ "size": 16, "multiscattering": false })";
  k.lut_params = R"({ "multiscattering": false })";
  const auto [sky, cube] = render(k);
  const Scene& scene = scene_;
  const Atmosphere& a = *scene.atmosphere;
  const physics::AtmosphereView view = physics::atmosphere_view(scene);
  const double mu_h = physics::mu_horizon(a, std::min(view.r, a.top_radius));
  for (int face = 0; face < 6; ++face) {
    double sum = 0, sum_error = 0;
    for (uint32_t j = 0; j < k.face; ++j) {
      for (uint32_t i = 0; i < k.face; ++i) {
        const glm::vec3 t = physics::cube::cube_texel_direction(face, glm::ivec2(int(i), int(j)), int(k.face));
        const Vec3 d{t.x, t.y, t.z};
        const double mu = physics::dot(d, view.up);
        if (std::abs(mu - mu_h) < 0.05) continue;
        const physics::SkyViewDirection sd = physics::sky_view_direction(view, d);
        const double r = std::min(view.r, a.top_radius);
        const Vec3 air = physics::sky_scattering(a, r, sd.mu, view.mu_s, physics::view_sun_cosine(sd.mu, sd.cos_azimuth, view.mu_s), {}, {});
        const Vec3 ground = physics::seen_ground_radiance(a, view, d);
        const Vec3 got = cube_texel(cube, face, i, j);
        for (size_t c = 0; c < 3; ++c) {
          const double want = 2 * (air[c] + ground[c]);
          sum += want;
          sum_error += std::abs(got[c] - want);
        }
      }
    }
    const double error = sum > 0 ? sum_error / sum : 0;
    std::printf("face %d against the single-scattering twin: relative mean %.3g\n", face, error);
    EXPECT_LT(error, 3e-3) << "face " << face;
  }
}

// Stress: a 1-texel face, a camera at 1000 km (the march from space), the sun 0.3 rad below
// the horizon: every texel finite and not negative.
TEST_P(SkyCube, StaysFiniteAtItsLimits) {
  for (const SkyCubeCase& k : {SkyCubeCase{2, 0.35, 1, "{ \"size\": 1 }"}, SkyCubeCase{1e6, 0.35, 8, "{}"},
                               SkyCubeCase{2, -0.3, 8, "{ \"size\": 8, \"sun_disk\": true }"}}) {
    const auto [sky, cube] = render(k);
    EXPECT_TRUE(all_finite(cube)) << k.altitude << " m, face " << k.face;
    EXPECT_TRUE(std::all_of(cube.rgba.begin(), cube.rgba.end(), [](float v) { return v >= 0; }));
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, SkyCube, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
