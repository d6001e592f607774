// Translucent shadows on translucent surfaces (translucent_shadow_map → translucency; RTR4
// §14.5.1), on both backends × the three variants: a red glass sheet (albedo (1, 0, 0),
// transmission 1, IOR 1.5) 1 m above a white veil (coverage 0.5, IOR 1) under a sun along
// (1, −1, 0), a black background and a black floor, so every pixel of the veil is its lit
// radiance alone. With the map wired the veil behind the sheet as the sun sees it is lit
// through the sheet: its red exactly (1 − F)·ρ of the untinted light (two fp16 steps), green
// and blue 0; every other pixel bit for bit as without the map (the veil casts no shadow;
// when it does, the map's limit below).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "physics/translucency.h"
#include "tests/gpu/config_output_fixture.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

// `veil_casts`: whether the veil is itself a caster of the translucent map.
std::string veil_under_glass(bool tinted, const std::string& variant, bool veil_casts = false) {
  return R"({ "output": { "size": [48, 48] },
  "scene": { "camera": { "position": [0, 8, 0.01], "target": [0, 0, 0], "fov_y_deg": 30 },
    "background": { "radiance": [0, 0, 0] },
    "lights": [ { "type": "directional", "direction": [1, -1, 0], "irradiance": [3, 3, 3] } ],
    "materials": { "black": { "albedo": [0, 0, 0] }, "veil": { "albedo": [1, 1, 1], "alpha": 0.5, "ior": 1 },
                   "red_glass": { "albedo": [1, 0, 0], "transmission": 1, "ior": 1.5 } },
    "objects": [ { "shape": "plane", "size": [20, 1, 20], "material": "black", "transform": { "translate": [0, -1, 0] } },
                 { "shape": "plane", "size": [6, 1, 6], "material": "veil", "cast_shadows": )" + std::string(veil_casts ? "true" : "false") + R"(, "transform": { "translate": [0, 0.5, 0] } },
                 { "shape": "plane", "size": [1, 1, 1], "material": "red_glass", "transform": { "translate": [-1.5, 1.5, 0] } } ] },
  "graph": { "passes": [
    { "name": "sun_shadow", "type": "shadow_map", "variant": "hard", "params": { "light": 0, "resolution": 512 } },)" + tint_pass(tinted) + R"(
    { "name": "lit", "type": "scene", "inputs": { "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view" } },
    { "name": "glass", "type": "translucency", "variant": ")" + variant + R"(",
      "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame",
                  "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view")" + tint_inputs(tinted) + R"( } } ],
    "outputs": ["glass.color"] } })";
}

class TranslucencyTranslucentShadow : public OnEachBackend<std::tuple<Backend, const char*>> {
 protected:
  Backend backend() const override { return std::get<0>(GetParam()); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  Texels color(bool tinted, bool veil_casts = false) {
    const LoadedConfig loaded =
        load_config_text("translucency_translucent_shadow.json", veil_under_glass(tinted, std::get<1>(GetParam()), veil_casts), registry_);
    Executor executor(device(), loaded.graph, &loaded.config.scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
};

TEST_P(TranslucencyTranslucentShadow, TheVeilBehindRedGlassIsLitThroughIt) {
  expect_tinted_by_red_glass(color(false), color(true), 60, "pixel");
}

// The map's known limit: one product of every caster's transmittance along the light's ray
// through a texel, and the nearest caster's depth. A receiver that casts into the map itself
// is tinted by its own transmittance too (here the veil's 1 − α = 0.5) wherever another
// caster lies in front of it; the CPU reference's shadow rays start past the receiver.
TEST_P(TranslucencyTranslucentShadow, AReceiverThatCastsIsTintedByItselfToo) {
  const Texels plain = color(false, true), tinted = color(true, true);
  const double red = red_glass_transmittance();
  int behind = 0;
  for (size_t p = 0; p < plain.rgba.size(); p += 4) {
    if (plain.rgba[p] == tinted.rgba[p] || tinted.rgba[p + 1] != 0.0f) continue;
    ++behind;
    EXPECT_NEAR(tinted.rgba[p], 0.5 * red * plain.rgba[p], fp16_steps(0.5 * red * plain.rgba[p])) << "pixel " << p / 4;
  }
  EXPECT_GT(behind, 60);
}

INSTANTIATE_TEST_SUITE_P(Variants, TranslucencyTranslucentShadow,
                         ::testing::Combine(::testing::ValuesIn(gpu_backends()), ::testing::Values("sorted", "weighted_oit", "depth_peeling")),
                         [](const ::testing::TestParamInfo<std::tuple<Backend, const char*>>& info) {
                           return std::string(std::get<1>(info.param)) + "_" + std::string(backend_name(std::get<0>(info.param)));
                         });

}  // namespace
}  // namespace volgraph::testing
