// The cloud layer's CPU reference (reference/clouds.h): coverage 0 is the image without
// clouds, a ray that misses the layer is untouched, the quadrature converges within the
// stated tolerance, and the noise texels are the twin's, quantised as rgba8 stores them.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/camera.h"
#include "physics/cloud_noise.h"
#include "reference/clouds.h"
#include "reference/renderer.h"
#include "tests/reference/test_scenes.h"

namespace volgraph::reference {
namespace {

// A plain seen from the ground looking 40° up, the sun ahead and to the right, a cumulus
// layer (docs/clouds.md's defaults but coverage 0.6), small noise textures for speed.
Scene cloud_scene(double coverage) {
  Scene s;
  s.camera.position = {0, 2, 0};
  s.camera.target = {0, 2 + std::tan(40 * M_PI / 180), -1};
  s.camera.fov_y_deg = 60;
  s.camera.far = 20000;
  s.background = {0.12, 0.2, 0.42};
  s.materials.push_back({.name = "ground", .albedo = {0.25, 0.3, 0.18}});
  s.objects.push_back({.name = "ground", .shape = Shape::plane, .size = {20000, 1, 20000}, .material = "ground"});
  s.lights.push_back({.name = "sun", .type = LightType::directional, .direction = {-0.3, -0.5, 0.81}, .irradiance = {3.0, 2.9, 2.7}});
  s.clouds = CloudLayer{.coverage = coverage, .extinction = 0.06, .shape_scale = 20000, .detail_scale = 2500};
  return s;
}

CloudReferenceSettings small_settings(int view_steps = 512, int light_steps = 32) {
  CloudReferenceSettings k;
  k.shape_size = 32, k.detail_size = 16, k.curl_size = 32;
  k.view_steps = view_steps, k.light_steps = light_steps;
  return k;
}

constexpr uint32_t kWidth = 16, kHeight = 9;

TEST(CloudReference, CoverageZeroIsExactlyTheImageWithoutClouds) {
  Scene without = cloud_scene(0);
  without.clouds.reset();
  const Scene with = cloud_scene(0);
  IntegrationSettings settings;
  settings.clouds = small_settings();
  const Renderer plain(without, settings), clouded(with, settings);
  ASSERT_NE(clouded.clouds(), nullptr);
  for (uint32_t j = 0; j < kHeight; ++j)
    for (uint32_t i = 0; i < kWidth; ++i) EXPECT_EQ(clouded.pixel_radiance(i, j, kWidth, kHeight), plain.pixel_radiance(i, j, kWidth, kHeight));
}

TEST(CloudReference, RayThatMissesTheLayerIsUntouched) {
  const CloudReference clouds(cloud_scene(1), small_settings());
  // Down at the ground, and along the horizon below the bottom's sphere from the ground:
  // the ground comes first, as cloud_march's identity.
  for (const Vec3& d : {Vec3{0, -1, 0}, Vec3{0.6, -0.8, 0}, Vec3{0, -1e-3, -1}}) {
    const CloudSample s = clouds.along(physics::normalize(d), std::numeric_limits<double>::infinity());
    EXPECT_EQ(s.transmittance, 1.0);
    EXPECT_EQ(s.radiance, (Vec3{0, 0, 0}));
  }
  // A surface in front of the layer clips the whole segment.
  const CloudSample clipped = clouds.along(Vec3{0, 1, 0}, 100);
  EXPECT_EQ(clipped.transmittance, 1.0);
  // The same ray without the surface does meet cloud at coverage 1.
  EXPECT_LT(clouds.along(Vec3{0, 1, 0}, std::numeric_limits<double>::infinity()).transmittance, 0.999);
}

TEST(CloudReference, ConvergesWithinItsStatedTolerance) {
  // The reference's own settings (IntegrationSettings' defaults) against twice as many
  // steps on both marches: every ray moves by less than kCloudReferenceTolerance.
  const Scene scene = cloud_scene(0.6);
  CloudReferenceSettings coarse = small_settings(CloudReferenceSettings{}.view_steps, CloudReferenceSettings{}.light_steps);
  CloudReferenceSettings fine = coarse;
  fine.view_steps *= 2, fine.light_steps *= 2;
  const CloudReference a(scene, coarse), b(scene, fine);
  int clouded = 0;
  for (uint32_t j = 0; j < kHeight; j += 2) {
    for (uint32_t i = 0; i < kWidth; i += 2) {
      const Vec3 d = physics::pixel_ray(scene.camera, kWidth, kHeight, i, j);
      const CloudSample x = a.along(d, std::numeric_limits<double>::infinity());
      const CloudSample y = b.along(d, std::numeric_limits<double>::infinity());
      if (x.transmittance < 0.99) ++clouded;
      EXPECT_NEAR(x.transmittance, y.transmittance, kCloudReferenceTolerance * 0.1) << i << "," << j;
      for (size_t c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(x.radiance[c] - y.radiance[c]), kCloudReferenceTolerance * std::max(y.radiance[c], 1e-3)) << i << "," << j;
    }
  }
  EXPECT_GT(clouded, 3);  // the case sees cloud
}

TEST(CloudReference, NoiseTexelsAreTheTwinQuantisedAsRgba8) {
  namespace twin = physics::cloud_noise;
  const int n = 16;
  const CloudTexture shape = cloud_shape_texture(n, 7), detail = cloud_detail_texture(n, 7), curl = cloud_curl_texture(n, 7);
  for (int z = 0; z < n; z += 5) {
    for (int y = 0; y < n; y += 3) {
      for (int x = 0; x < n; ++x) {
        const glm::vec3 uvw = (glm::vec3(float(x), float(y), float(z)) + 0.5f) / float(n);
        const glm::vec4 s = twin::cloud_shape_texel(uvw, 7), d = twin::cloud_detail_texel(uvw, 7);
        const glm::vec4 c = twin::cloud_curl_texel(glm::vec2(uvw.x, uvw.y), 1.0f / float(n), 7);
        for (int k = 0; k < 4; ++k) {
          EXPECT_EQ(shape.texel(x, y, z)[size_t(k)], quantise_unorm8(s[k]));
          EXPECT_EQ(detail.texel(x, y, z)[size_t(k)], quantise_unorm8(d[k]));
          if (z == 0) EXPECT_EQ(curl.texel(x, y, 0)[size_t(k)], quantise_unorm8(c[k]));
          EXPECT_LE(std::abs(shape.texel(x, y, z)[size_t(k)] - s[k]), 0.5f / 255 + 1e-6f);
        }
        // The linear filter at a texel centre is the texel; repeat wraps by one tile.
        const std::array<float, 4> at = shape.sample(uvw.x, uvw.y, uvw.z), wrapped = shape.sample(uvw.x + 1, uvw.y - 1, uvw.z + 2);
        for (size_t k = 0; k < 4; ++k) {
          EXPECT_NEAR(at[k], shape.texel(x, y, z)[k], 1e-6f);
          EXPECT_NEAR(wrapped[k], at[k], 1e-5f);
        }
      }
    }
  }
}

// `volgraph reference` takes the config's cloud_noise sizes and cloud_march parameters.
TEST(CloudReference, SettingsComeFromTheConfigsCloudPasses) {
  // The registry outlives the graphs: their passes point at its decls (load_shipped's does not).
  PassRegistry registry;
  register_builtin_passes(registry);
  const std::string configs = std::string(::volgraph::testing::source_dir()) + "/configs/";
  const LoadedConfig loaded = load_config(configs + "tests/oracle_clouds.json", registry);
  const CloudReferenceSettings k = cloud_reference_settings(loaded.graph, loaded.params);
  EXPECT_EQ(k.shape_size, 64);
  EXPECT_EQ(k.detail_size, 32);
  EXPECT_EQ(k.curl_size, 64);
  EXPECT_EQ(k.light_distance, 2000);
  EXPECT_EQ(k.octaves, 3);
  const LoadedConfig demo = load_config(configs + "demo_clouds.json", registry);
  EXPECT_EQ(cloud_reference_settings(demo.graph, demo.params).ambient, (Vec3{0.25, 0.3, 0.4}));
}

}  // namespace
}  // namespace volgraph::reference
