// The reference image is the same bit for bit with any thread count (rows pulled from an
// atomic counter, each pixel computed alone): the foggy demo and the noisy-volume demo
// on 1 thread against 3, 7 and more threads than the image has rows, compared byte for
// byte.
#include <cstring>

#include <gtest/gtest.h>

#include "reference/image_render.h"
#include "reference/renderer.h"
#include "tests/reference/test_scenes.h"

namespace volgraph::reference {
namespace {

constexpr uint32_t kWidth = 24, kHeight = 10;

bool same_bits(const ReferenceImage& a, const ReferenceImage& b) {
  return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(double)) == 0;
}

void expect_the_same_image_on_any_thread_count(const Scene& scene) {
  const Renderer renderer(scene);
  const ReferenceImage one = render_image(renderer, {.width = kWidth, .height = kHeight, .threads = 1});
  for (unsigned threads : {3u, 7u, 4 * kHeight}) {
    const ReferenceImage many = render_image(renderer, {.width = kWidth, .height = kHeight, .threads = threads});
    EXPECT_TRUE(same_bits(one, many)) << threads << " threads";
  }
}

TEST(ReferenceThreads, FoggyDemoIsTheSameBitForBitOnAnyThreadCount) {
  LoadedConfig loaded = load_shipped("demo_primitives.json", kWidth, kHeight);
  add_demo_fog(loaded.config.scene);
  expect_the_same_image_on_any_thread_count(loaded.config.scene);
}

TEST(ReferenceThreads, NoisyVolumeIsTheSameBitForBitOnAnyThreadCount) {
  expect_the_same_image_on_any_thread_count(load_shipped("demo_noise_volume.json", kWidth, kHeight).config.scene);
}

}  // namespace
}  // namespace volgraph::reference
