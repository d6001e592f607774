// Translucent shadows in the fog (translucent_shadow_map → froxel_scatter; RTR4 §14.5.1), on
// both backends: a red glass sheet (albedo (1, 0, 0), transmission 1, IOR 1.5) hangs in a
// homogeneous fog under a slanted sun (hard shadow lookups); the light each froxel scatters
// with the map wired is the light without it, times the sheet's transmittance (1 − F)·ρ for
// the froxels behind the sheet as the sun sees them (red, within two fp16 steps; green and
// blue 0), and the same bit for bit everywhere else.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "physics/translucency.h"
#include "tests/gpu/config_output_fixture.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

// Seen from 8 m above, looking down at the beam.
std::string fog_under_glass(bool tinted) {
  return "{ " + red_glass_in_fog("[32, 32]", R"({ "position": [0, 8, 0.01], "target": [0, 0, 0], "fov_y_deg": 30 })") + R"(,
  "graph": { "passes": [
    { "name": "sun_shadow", "type": "shadow_map", "variant": "hard", "params": { "light": 0, "resolution": 512 } },)" + tint_pass(tinted) + R"(
    { "name": "fog_media", "type": "froxel_voxelize", "params": { "tile": 2, "slices": 32, "near": 0.1, "far": 12, "distribution": "linear", "jitter": false } },
    { "name": "fog_light", "type": "froxel_scatter", "variant": "hg",
      "inputs": { "media_scattering": "fog_media.media_scattering", "media_emission": "fog_media.media_emission",
                  "frame": "fog_media.frame", "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view")" + tint_inputs(tinted) + R"( } } ],
    "outputs": ["fog_light.in_scatter"] } })";
}

class FroxelScatterTranslucentShadow : public ConfigOutputOnEachBackend {
 protected:
  Texels in_scatter(bool tinted) { return first_output("froxel_translucent_shadow.json", fog_under_glass(tinted)); }
};

TEST_P(FroxelScatterTranslucentShadow, TheFogBehindRedGlassCarriesItsTransmittance) {
  expect_tinted_by_red_glass(in_scatter(false), in_scatter(true), 20, "froxel");
}

INSTANTIATE_TEST_SUITE_P(Backends, FroxelScatterTranslucentShadow, ::testing::ValuesIn(gpu_backends()),
                         backend_test_name);

}  // namespace
}  // namespace volgraph::testing
