// opacity_shadow_map (Kim & Neumann 2001) on both backends: the dense box shadows the fog
// layer under it through the map as the march does, and the map dims surfaces under the
// media. Fixture: froxel_fog.h.
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "tests/gpu/froxel_fog.h"

namespace volgraph::testing {
namespace {

class OpacityShadowMap : public FroxelFogFixture {};

// The same shadow by the other volumetric-shadow variant: light 0 casts shadows, its
// shadow map's view holds the media volumes, and an opacity shadow map of 64 layers over
// it replaces the march (shadow_steps 0). The layer's own optical depth toward the light
// is linear in height (trilinear lookups reproduce it) and the box's is whole below it:
// the ratio is e^(−1) as before, to 3 %: the march of 2 steps a layer and fp16 τ, and the
// froxels that the layer's bottom face cuts — they hold its medium in part (froxel_voxelize
// averages it over the froxel) and are lit at their centre, which may lie below the layer,
// outside the media the map was fitted to (where those centres fall moves the ratio:
// measured −2.2 % at 64 slices, +2.4 % at 256). The image agrees with the 256-step
// march's to 3 % wherever the layer is lit.
TEST_P(OpacityShadowMap, ADenseBoxShadowsTheFogUnderItThroughAnOpacityShadowMap) {
  const Texels shadowed = render(load(layer_under_box_by_opacity_map(true)));
  const Texels marched = render(load(layer_under_box(true, 256)));
  expect_box_shadow(render(load(layer_under_box_by_opacity_map(false))), shadowed,
                    [&](size_t k) { EXPECT_NEAR(shadowed.rgba[k], marched.rgba[k], 3e-2 * marched.rgba[k]) << k / 4; }, 3e-2);
}

// Surfaces too: a floor (ρ 0.5, y = −0.5) under the fog layer (τ 1 straight up, over
// −4 < z < 0) and the box (τ 1, over −10 < x < 0) receives E·e^(−τ) from the light
// overhead, so its radiance is ρ/π·3·e^(−τ) — read where the floor is at least 0.5 m from
// the media's edges (the map's texels blend across them). 1 %: fp16 τ, and 8 march steps a
// layer (0.21 m layers here) put each of the layer's edges within ±0.013 m (τ ±0.007).
// The graph renders the lit scene alone (no fog in front of the floor).
TEST_P(OpacityShadowMap, TheOpacityShadowMapDimsSurfacesUnderTheMedia) {
  std::ostringstream text;
  text << R"({ "output": { "size": [)" << kFroxelFogWidth << ", " << kFroxelFogHeight << R"(] },
  "scene": { "camera": )" << kCameraAtTheLayer << R"(, "media": )" << layer_under_box_media(true) << R"(,
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "floor", "shape": "plane", "size": [40, 1, 40], "material": "grey", "transform": { "translate": [0, -0.5, 0] } } ],
    "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3] } ] },
  "graph": { "passes": [
    { "name": "sun_shadow", "type": "shadow_map", "params": { "resolution": 256 } },
    { "name": "media_shadow", "type": "opacity_shadow_map", "params": { "resolution": 64, "layers": 64, "steps_per_layer": 8 },
      "inputs": { "light_view": "sun_shadow.light_view" } },
    { "name": "lit", "type": "scene", "inputs": { )" << (kOpacityShadowInputs + 2) << R"( } },
    { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "lit.color" } } ],
    "outputs": ["out.output"] } })";
  const LoadedConfig config = load_config_text("floor.json", text.str(), registry_);
  const Texels t = render(config);
  const physics::ViewRays rays = physics::view_rays(config.config.scene.camera, double(kFroxelFogWidth) / kFroxelFogHeight);
  size_t checked[2] = {0, 0};
  for (uint32_t j = 0; j < kFroxelFogHeight; ++j) {
    for (uint32_t i = 0; i < kFroxelFogWidth; ++i) {
      const Vec3 d = physics::view_ray(rays, (i + 0.5) / kFroxelFogWidth * 2 - 1, 1 - (j + 0.5) / kFroxelFogHeight * 2);
      if (d[1] >= 0) continue;
      const double t_floor = (-0.5 - rays.position[1]) / d[1];
      const double x = rays.position[0] + t_floor * d[0], z = rays.position[2] + t_floor * d[2];
      const bool under_layer = z > -4 && z < 0, under_box = x > -10 && x < 0;
      if (std::abs(x) < 0.5 || std::abs(x + 10) < 0.5 || std::abs(z) < 0.5 || std::abs(z + 4) < 0.5 || z < -15) continue;
      const double want = 0.5 / M_PI * 3 * std::exp(-(under_layer ? 1.0 : 0.0) - (under_box ? 1.0 : 0.0));
      ++checked[under_layer];
      EXPECT_NEAR(t.rgba[4 * (j * kFroxelFogWidth + i)], want, 1e-2 * want) << i << ", " << j << " x " << x << " z " << z;
    }
  }
  EXPECT_GT(checked[0], 20u);
  EXPECT_GT(checked[1], 20u);
}

// Deep opacity maps (Yuksel & Keyser 2008): a homogeneous box (σa 1, 2 m tall) lit from
// straight above, its light view fitted to it. Every column through the box enters it at its top, so
// deep layer k lies kΔ below it and holds τ = σt·kΔ exactly (Δ 0.25 m, 8 layers: all inside
// the box, each march segment wholly in the medium; 1e-3 relative: fp16). Layer 0's alpha
// records the layers' start and layer 1's their span, as fractions of the column: layer 0's
// centre start + span/2n lies on the box's top, which the regular map's τ places too.
TEST_P(OpacityShadowMap, TheDeepMapsLayersStartAtTheFirstMediumOfEachColumn) {
  const auto map_of = [&](const char* variant) {
    std::ostringstream text;
    text << R"({ "output": { "size": [8, 8] },
    "scene": { "camera": )" << kCameraAtTheLayer << R"(,
      "media": { "volumes": [ { "shape": "box", "size": [4, 2, 4], "sigma_s": [0, 0, 0], "sigma_a": [1, 1, 1],
                                "transform": { "translate": [0, 1, -2] } } ] },
      "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3] } ] },
    "graph": { "passes": [
      { "name": "sun_shadow", "type": "shadow_map", "params": { "resolution": 64 } },
      { "name": "media_shadow", "type": "opacity_shadow_map", "variant": ")" << variant << R"(",
        "params": { "resolution": 8, "layers": 8, "steps_per_layer": 4, "layer_spacing": 0.25 },
        "inputs": { "light_view": "sun_shadow.light_view" } } ],
      "outputs": ["media_shadow.optical_depth"] } })";
    const LoadedConfig config = load_config_text("deep.json", text.str(), registry_);
    return render(config);
  };
  const Texels deep = map_of("deep");
  ASSERT_EQ(deep.depth, 8u);
  const uint32_t n = deep.depth, columns = deep.width * deep.height;
  uint32_t through_the_box = 0;
  for (uint32_t column = 0; column < columns; ++column) {
    // A column that misses the box (the view's margin around it) holds τ 0 throughout.
    const bool hits = deep.rgba[4 * (size_t(n - 1) * columns + column)] > 0;
    through_the_box += hits;
    for (uint32_t k = 0; k < n; ++k) {
      const size_t texel = 4 * (size_t(k) * columns + column);
      const double want = hits ? 1.0 * 0.25 * k : 0.0;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(deep.rgba[texel + c], want, 1e-3 * want + 1e-4) << "column " << column << " layer " << k;
    }
    const double start = deep.rgba[4 * column + 3], span = deep.rgba[4 * (size_t(columns) + column) + 3];
    EXPECT_GT(span, 0.0) << column;
    // Layer 0's centre (the box's top) as a fraction of the column, by the record.
    const double top = start + span / (2.0 * n);
    EXPECT_GE(top, -1e-3) << column;
    EXPECT_LT(top, 1.0) << column;
    // The record's spacing: the span is n·Δ of the column, the same for every column of a
    // directional light's (orthographic) view.
    EXPECT_NEAR(span, deep.rgba[4 * (size_t(columns) + 0) + 3], 1e-3 * span) << column;
  }
  EXPECT_GE(through_the_box, 4u);  // the central columns at least
  // The regular map's record: start 0, span 1 (its texture coordinate is the fraction itself).
  const Texels regular = map_of("layered");
  for (uint32_t column = 0; column < columns; ++column) {
    EXPECT_EQ(regular.rgba[4 * column + 3], 0.0f) << column;
    EXPECT_EQ(regular.rgba[4 * (size_t(columns) + column) + 3], 1.0f) << column;
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, OpacityShadowMap, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
