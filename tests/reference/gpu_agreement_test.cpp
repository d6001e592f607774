// The reference against the GPU on configs/demo_primitives.json at 64×36: its golden
// image (tests/golden/, the Vulkan render tone-mapped by the config's ACES composite)
// against the reference's radiance through the same tone map (physics/tonemap.h), away
// from shadow and silhouette edges (pixels whose 3×3 neighbourhood sees one object and
// one sun visibility); and the image is the same bit for bit on 1 and 2 threads.
#include <cstdio>

#include <gtest/gtest.h>

#include "physics/camera.h"
#include "physics/tonemap.h"
#include "reference/image_render.h"
#include "reference/renderer.h"
#include "tests/reference/test_scenes.h"
#include "tools/image_io.h"
#include "tests/support/source_dir.h"

namespace volgraph::reference {
namespace {

// What a pixel's centre sees: the object (−1 for none) and whether the sun reaches it.
struct PixelClass {
  int object = -1;
  bool sunlit = false;
  bool operator==(const PixelClass&) const = default;
};

std::vector<PixelClass> classify(const Renderer& renderer, uint32_t w, uint32_t h) {
  std::vector<PixelClass> out(size_t(w) * h);
  const Scene& scene = renderer.scene();
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      const std::optional<SurfaceHit> hit = renderer.surface_hit(physics::pixel_ray(scene.camera, w, h, i, j));
      if (!hit) continue;
      out[size_t(j) * w + i] = {int(renderer.triangles().attributes[hit->triangle].object),
                                renderer.light_visible(scene.lights[0], hit->position)};
    }
  }
  return out;
}

bool interior(const std::vector<PixelClass>& classes, uint32_t w, uint32_t h, uint32_t i, uint32_t j) {
  if (i == 0 || j == 0 || i + 1 == w || j + 1 == h) return false;
  for (uint32_t y = j - 1; y <= j + 1; ++y) {
    for (uint32_t x = i - 1; x <= i + 1; ++x) {
      if (!(classes[size_t(y) * w + x] == classes[size_t(j) * w + i])) return false;
    }
  }
  return true;
}

TEST(ReferenceVersusGpu, DemoPrimitivesMatchesTheGoldenImageAwayFromEdges) {
  const uint32_t w = 64, h = 36;
  const LoadedConfig loaded = load_shipped("demo_primitives.json", w, h);
  const Renderer renderer(loaded.config.scene);
  const ReferenceImage image = render_image(renderer, {.width = w, .height = h, .threads = 2});
  const Image golden = read_pfm(std::string(::volgraph::testing::source_dir()) + "/tests/golden/demo_primitives.pfm");
  ASSERT_EQ(golden.width, w);
  ASSERT_EQ(golden.height, h);
  const std::vector<PixelClass> classes = classify(renderer, w, h);
  double worst = 0, sum = 0;
  size_t compared = 0;
  for (uint32_t j = 0; j < h; ++j) {
    for (uint32_t i = 0; i < w; ++i) {
      if (!interior(classes, w, h, i, j)) continue;
      const physics::Rgb mapped = physics::tone_map(image.at(i, j), 0, physics::ToneMap::aces);  // the config's composite
      for (size_t c = 0; c < 3; ++c) {
        const double e = std::abs(mapped[c] - golden.rgba[(size_t(j) * w + i) * 4 + c]);
        worst = std::max(worst, e);
        sum += e;
      }
      ++compared;
    }
  }
  std::printf("reference vs GPU golden, demo_primitives 64x36: %zu of %u pixels compared, mean abs error %.2e, max %.2e (tone-mapped)\n",
              compared, w * h, sum / double(3 * compared), worst);
  EXPECT_GT(compared, size_t(w * h) / 2);
  EXPECT_LT(sum / double(3 * compared), 5e-4) << "mean absolute error of tone-mapped values";
  EXPECT_LT(worst, 2e-3) << "largest absolute error of a tone-mapped value";
}

TEST(ReferenceVersusGpu, ImageIsTheSameOnOneAndTwoThreads) {
  const LoadedConfig loaded = load_shipped("demo_primitives.json", 64, 36);
  const Renderer renderer(loaded.config.scene);
  const ReferenceImage one = render_image(renderer, {.width = 64, .height = 36, .samples_per_axis = 2, .threads = 1});
  const ReferenceImage two = render_image(renderer, {.width = 64, .height = 36, .samples_per_axis = 2, .threads = 2});
  EXPECT_TRUE(one.rgb == two.rgb);
}

}  // namespace
}  // namespace volgraph::reference
