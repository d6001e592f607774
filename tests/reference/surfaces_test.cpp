// The reference renderer's surfaces against closed forms (DESIGN.md units): a Lambertian
// wall under a directional light is ρE/π in every pixel; under a point light each pixel
// is ρ/π · I · cos θ / d² at the point its ray meets the plane; in full shadow exactly 0
// (pass parameters such as the ambient term are not part of the scene).
#include <cmath>

#include <gtest/gtest.h>

#include "physics/camera.h"
#include "reference/image_render.h"
#include "reference/renderer.h"
#include "tests/reference/test_scenes.h"

namespace volgraph::reference {
namespace {

using physics::dot;
using physics::sub;

TEST(ReferenceSurfaces, LitLambertianWallIsRhoEOverPi) {
  const LoadedConfig loaded = load_shipped("tests/lambert_plane_lit.json", 32, 24);
  const Renderer renderer(loaded.config.scene);
  const ReferenceImage image = render_image(renderer, {.width = 32, .height = 24, .threads = 2});
  const double expected = 0.5 / M_PI * 3.14159265358979;  // the config's E is π to 15 digits
  for (double value : image.rgb) ASSERT_DOUBLE_EQ(value, expected);
}

TEST(ReferenceSurfaces, PointLightOnAPlaneIsTheInverseSquareLaw) {
  Scene scene = plane_scene({0.2, 3, 0.5}, 0.6);
  Light light;
  light.type = LightType::point;
  light.position = {0.7, 1.5, -0.4};
  light.intensity = {5, 4, 3};
  scene.lights.push_back(light);
  const Renderer renderer(scene);
  const uint32_t w = 24, h = 16;
  double worst = 0;
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      const Vec3 d = physics::pixel_ray(scene.camera, w, h, i, j);
      const double t = -scene.camera.position[1] / d[1];  // where the ray meets y = 0
      const Vec3 p = physics::add(scene.camera.position, physics::scaled(d, t));
      const Vec3 to_light = sub(light.position, p);
      const double d2 = dot(to_light, to_light), cos_theta = to_light[1] / std::sqrt(d2);
      const Vec3 got = renderer.pixel_radiance(i, j, w, h);
      for (size_t c = 0; c < 3; ++c) {
        const double expected = 0.6 / M_PI * light.intensity[c] * cos_theta / d2;
        worst = std::max(worst, std::abs(got[c] - expected) / expected);
      }
    }
  }
  EXPECT_LT(worst, 1e-12) << "largest relative error";
}

TEST(ReferenceSurfaces, FullShadowIsExactlyZeroAndTheOpenPlaneRhoEOverPi) {
  const uint32_t w = 96, h = 48;
  const LoadedConfig loaded = load_shipped("tests/full_shadow.json", w, h);
  const Renderer renderer(loaded.config.scene);
  const double lit = 0.5 / M_PI * 3.14159265358979;
  size_t shadowed = 0, open = 0;
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      const std::optional<SurfaceHit> hit = renderer.surface_hit(physics::pixel_ray(loaded.config.scene.camera, w, h, i, j));
      if (!hit || std::abs(hit->position[1]) > 1e-12) continue;  // the plane's pixels only
      const double x = std::abs(hit->position[0]), z = std::abs(hit->position[2]);
      const Vec3 l = renderer.surface_radiance(*hit);
      if (x < 1 - 1e-9 && z < 1 - 1e-9) {  // under the 2 m slab, the sun straight down
        ++shadowed;
        for (double v : l) ASSERT_EQ(v, 0.0) << "pixel " << i << ", " << j;
      } else if (x > 1 + 1e-9 || z > 1 + 1e-9) {
        ++open;
        for (double v : l) ASSERT_DOUBLE_EQ(v, lit) << "pixel " << i << ", " << j;
      }
    }
  }
  EXPECT_GT(shadowed, 30u);
  EXPECT_GT(open, 100u);
}

TEST(ReferenceSurfaces, BackgroundWhereNothingIsHitAndEmissionUnchanged) {
  Scene scene = plane_scene({0, 3, 0.001}, 0.5, 0.5);  // a small plane: most rays miss it
  scene.background = {0.25, 0.5, 1.0};
  scene.materials[0].emissive = {2, 3, 4};
  const Renderer renderer(scene);
  EXPECT_EQ(renderer.pixel_radiance(0, 0, 16, 16), scene.background);
  EXPECT_EQ(renderer.pixel_radiance(8, 8, 16, 16), scene.materials[0].emissive);  // no light: emission alone
}

TEST(ReferenceSurfaces, PlaneSeenFromBelowIsLitOnTheSideSeen) {
  Scene scene = plane_scene({0, -3, 0.001}, 0.5);
  Light sun;
  sun.direction = {0, 1, 0};  // shining up at the plane's underside
  sun.irradiance = {2, 2, 2};
  scene.lights.push_back(sun);
  const Renderer renderer(scene);
  EXPECT_DOUBLE_EQ(renderer.pixel_radiance(8, 8, 16, 16)[0], 0.5 / M_PI * 2);
}

}  // namespace
}  // namespace volgraph::reference
