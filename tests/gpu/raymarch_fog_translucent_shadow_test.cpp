// Translucent shadows in the ray-marched fog (translucent_shadow_map → raymarch_fog; RTR4
// §14.5.1), on both backends: a red glass sheet (albedo (1, 0, 0), transmission 1) hangs in a
// homogeneous fog under a slanted sun, seen from the side so that view rays cross its beam.
// With the map wired no pixel gains light; the pixels whose rays cross the beam lose green and
// blue alike (the sheet passes none) and red by a smaller share (it passes (1 − F) of it).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tests/gpu/config_output_fixture.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

// Seen from the side, so that view rays cross the beam.
std::string marched_fog_under_glass(bool tinted) {
  return "{ " + red_glass_in_fog("[48, 32]", R"({ "position": [0, 1, 6], "target": [-0.5, 0.8, 0], "fov_y_deg": 50 })") + R"(,
  "graph": { "passes": [
    { "name": "sun_shadow", "type": "shadow_map", "variant": "hard", "params": { "light": 0, "resolution": 512 } },)" + tint_pass(tinted) + R"(
    { "name": "lit", "type": "scene" },
    { "name": "fog", "type": "raymarch_fog", "variant": "hg", "params": { "steps": 128, "jitter": false, "max_distance": 20 },
      "inputs": { "depth": "lit.depth", "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view")" + tint_inputs(tinted) + R"( } } ],
    "outputs": ["fog.fog_scattering"] } })";
}

class RaymarchFogTranslucentShadow : public ConfigOutputOnEachBackend {
 protected:
  Texels scattering(bool tinted) { return first_output("raymarch_translucent_shadow.json", marched_fog_under_glass(tinted)); }
};

TEST_P(RaymarchFogTranslucentShadow, RaysThroughTheBeamLoseGreenAndBlueMoreThanRed) {
  const Texels plain = scattering(false), tinted = scattering(true);
  ASSERT_EQ(plain.rgba.size(), tinted.rgba.size());
  int crossing = 0;
  for (size_t p = 0; p < plain.rgba.size(); p += 4) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(tinted.rgba[p + k], plain.rgba[p + k] + fp16_steps(plain.rgba[p + k])) << "pixel " << p / 4 << " channel " << k;
    }
    const float green_lost = plain.rgba[p + 1] - tinted.rgba[p + 1];
    if (green_lost <= fp16_steps(plain.rgba[p + 1])) continue;
    ++crossing;
    EXPECT_NEAR(tinted.rgba[p + 2], tinted.rgba[p + 1], fp16_steps(tinted.rgba[p + 1])) << "pixel " << p / 4;
    EXPECT_GT(tinted.rgba[p] / plain.rgba[p], tinted.rgba[p + 1] / plain.rgba[p + 1]) << "pixel " << p / 4;
  }
  EXPECT_GT(crossing, 10) << "pixels whose rays cross the sheet's beam";
}

INSTANTIATE_TEST_SUITE_P(Backends, RaymarchFogTranslucentShadow, ::testing::ValuesIn(gpu_backends()),
                         backend_test_name);

}  // namespace
}  // namespace volgraph::testing
