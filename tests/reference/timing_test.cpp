// How long the reference takes on two threads at 320×180 (printed, not asserted: the
// machine is shared): the helmet demo (surfaces, textures, a spot and a point light)
// and the primitives demo in fog (global fog, height fog and a fog ball, single
// scattering of the sun); and that the fog image is the same on one and two threads.
#include <chrono>
#include <cstdio>

#include <gtest/gtest.h>

#include "reference/image_render.h"
#include "reference/renderer.h"
#include "tests/reference/test_scenes.h"

namespace volgraph::reference {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// demo_primitives with fog everywhere, denser near the ground, and a ball of thick fog.
void add_fog(Scene& scene) {
  scene.media.fog = Medium{.sigma_s = {0.02, 0.025, 0.03}, .sigma_a = {0.005, 0.005, 0.005}, .g = 0.3};
  scene.media.height_fog = HeightFog{.medium = {.sigma_s = {0.1, 0.1, 0.1}, .sigma_a = {0.01, 0.01, 0.01}, .g = 0.5},
                                     .base_height = 0, .falloff = 1.5};
  MediumVolume ball{.shape = Shape::sphere, .medium = {.sigma_s = {0.6, 0.5, 0.4}, .sigma_a = {0.05, 0.05, 0.05}, .g = -0.2}};
  ball.transform.translate = {0, 1.8, 1};
  ball.transform.scale = {0.8, 0.8, 0.8};
  scene.media.volumes.push_back(ball);
}

TEST(ReferenceTiming, HelmetDemoAt320x180) {
  const auto start = std::chrono::steady_clock::now();
  const LoadedConfig loaded = load_shipped("demo_helmet.json", 320, 180);
  const Renderer renderer(loaded.config.scene);
  const double build = seconds_since(start);
  const auto render_start = std::chrono::steady_clock::now();
  const ReferenceImage image = render_image(renderer, {.width = 320, .height = 180, .threads = 2});
  std::printf("reference timing: demo_helmet 320x180, %zu triangles, CPU 2 threads: load and BVH %.2f s, render %.2f s\n",
              renderer.triangles().triangles.size(), build, seconds_since(render_start));
  EXPECT_EQ(image.rgb.size(), size_t(320 * 180 * 3));
}

TEST(ReferenceTiming, FoggyPrimitivesAt320x180) {
  LoadedConfig loaded = load_shipped("demo_primitives.json", 320, 180);
  add_fog(loaded.config.scene);
  const Renderer renderer(loaded.config.scene);
  const auto start = std::chrono::steady_clock::now();
  const ReferenceImage image = render_image(renderer, {.width = 320, .height = 180, .threads = 2});
  std::printf("reference timing: demo_primitives with fog 320x180, CPU 2 threads, relative tolerance %.0e: render %.2f s\n",
              IntegrationSettings{}.relative_tolerance, seconds_since(start));
  for (double v : image.rgb) ASSERT_TRUE(std::isfinite(v) && v >= 0);
}

TEST(ReferenceTiming, FoggyImageIsTheSameOnOneAndTwoThreads) {
  LoadedConfig loaded = load_shipped("demo_primitives.json", 32, 18);
  add_fog(loaded.config.scene);
  const Renderer renderer(loaded.config.scene);
  const ReferenceImage one = render_image(renderer, {.width = 32, .height = 18, .threads = 1});
  const ReferenceImage two = render_image(renderer, {.width = 32, .height = 18, .threads = 2});
  EXPECT_TRUE(one.rgb == two.rgb);
}

}  // namespace
}  // namespace volgraph::reference
