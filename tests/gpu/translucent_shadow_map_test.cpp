// Translucent shadows (translucent_shadow_map → scene; RTR4 §7.8, §14.5.1), on both backends.
// A white floor seen from above under a slanted sun (hard shadow lookups: each pixel is lit,
// tinted or shadowed, no PCF blend), with a red glass sheet above it, out of the camera's view,
// whose shadow falls in it:
// - the floor under the sheet's shadow is the floor without it × the sheet's transmittance,
//   physics::surface_layer's at the sun's angle ((1 − F)·ρ, F Schlick's for IOR 1.5), within
//   two fp16 steps; every other pixel is bit for bit as without the sheet;
// - an opaque box above the sheet still shadows fully (black, no ambient), and the sheet
//   behind it is not in the transmittance map (1 there);
// - a receiver between the sheet and the sun (casting no shadow itself) is not tinted;
// - no translucent caster: the map is 1 everywhere and the floor is as without the pass;
// - stress (IOR 1 and 4, transmission 0 and 1): every value finite, transmission 0 black;
// - against the CPU reference with translucent shadows on: relative mean error Σ|gpu − ref| / Σ ref.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/translucency.h"
#include "reference/image_render.h"
#include "tests/gpu/backends.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {
namespace {

// The sheet: 1 m square at height 1.5 around x = −2.5 (the camera, 8 m up with a 30° view,
// sees |x| < 1.7 there); the sun along (1, −1, 0) moves its shadow 1.5 m along +x.
std::string glass(const std::string& material) {
  return R"(, { "shape": "plane", "size": [1, 1, 1], "material": ")" + material + R"(", "transform": { "translate": [-2.5, 1.5, 0] } })";
}
// An opaque box above the sheet, covering it from the sun.
constexpr const char* kBoxAbove =
    R"(, { "shape": "box", "size": [2, 0.4, 1.6], "material": "white", "transform": { "translate": [-3.4, 2.5, 0] } })";

std::string tinted_floor_and(const std::string& objects, bool translucent_shadows = true) {
  const std::string scene_inputs = translucent_shadows
      ? R"("shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view",
           "translucent_shadow": "tint.transmittance", "translucent_shadow_depth": "tint.depth")"
      : R"("shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view")";
  const std::string tint = translucent_shadows
      ? R"({ "name": "tint", "type": "translucent_shadow_map", "params": { "resolution": 512 },
             "inputs": { "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view" } },)"
      : "";
  return R"({ "output": { "size": [32, 32] },
  "scene": { "camera": { "position": [0, 8, 0.01], "target": [0, 0, 0], "fov_y_deg": 30 },
    "background": { "radiance": [0, 0, 0] },
    "lights": [ { "type": "directional", "direction": [1, -1, 0], "irradiance": [3, 3, 3] } ],
    "materials": { "white": { "albedo": [1, 1, 1] },
                   "red_glass": { "albedo": [1, 0, 0], "transmission": 1, "ior": 1.5 },
                   "ior1": { "albedo": [1, 1, 1], "transmission": 1, "ior": 1 },
                   "ior4": { "albedo": [0.5, 1, 1], "transmission": 1, "ior": 4 },
                   "dark": { "albedo": [1, 1, 1], "transmission": 0, "ior": 1.5, "alpha": 0.999, "alpha_mode": "blend" } },
    "objects": [ { "shape": "plane", "size": [20, 1, 20], "material": "white" } )" + objects + R"( ] },
  "graph": { "passes": [
    { "name": "sun_shadow", "type": "shadow_map", "variant": "hard", "params": { "light": 0, "resolution": 512 } },)" + tint + R"(
    { "name": "lit", "type": "scene", "inputs": { )" + scene_inputs + R"( } } ],
    "outputs": ["lit.color")" + (translucent_shadows ? R"(, "tint.transmittance")" : "") + R"(] } })";
}

class TranslucentShadow : public OnEachBackend<Backend> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  // The floor's colour, and the transmittance map where the graph has one.
  std::pair<Texels, Texels> render(const std::string& text) {
    const LoadedConfig loaded = load_config_text("translucent_shadow.json", text, registry_);
    scene_ = loaded.config.scene;
    Executor executor(device(), loaded.graph, &scene_, {});
    executor.run_frame();
    return {executor.read_output(0), loaded.graph.outputs.size() > 1 ? executor.read_output(1) : Texels{}};
  }
  PassRegistry registry_;
  Scene scene_;
};


bool all_one(const Texels& t) {
  for (size_t p = 0; p < t.rgba.size(); p += 4) {
    if (t.rgba[p] != 1.0f || t.rgba[p + 1] != 1.0f || t.rgba[p + 2] != 1.0f) return false;
  }
  return true;
}

TEST_P(TranslucentShadow, RedGlassColoursTheFloorByItsTransmittance) {
  const Texels floor = render(tinted_floor_and("")).first;
  const Texels tinted = render(tinted_floor_and(glass("red_glass"))).first;
  // The sheet's normal is +y, the sun 45° off it: (1 − F)·ρ with one interface.
  const double cos_sun = std::sqrt(0.5);
  const double red = 1.0 - physics::interface_reflectance(1.5, cos_sun);
  int under = 0, elsewhere_changed = 0;
  for (size_t p = 0; p < floor.rgba.size(); p += 4) {
    const bool same = floor.rgba[p] == tinted.rgba[p] && floor.rgba[p + 1] == tinted.rgba[p + 1] && floor.rgba[p + 2] == tinted.rgba[p + 2];
    if (same) continue;
    if (tinted.rgba[p + 1] != 0.0f || tinted.rgba[p + 2] != 0.0f) {
      ++elsewhere_changed;
      continue;
    }
    ++under;
    EXPECT_NEAR(tinted.rgba[p], red * floor.rgba[p], fp16_steps(red * floor.rgba[p])) << "texel " << p / 4;
  }
  EXPECT_GT(under, 20) << "the sheet's shadow on the floor";
  EXPECT_EQ(elsewhere_changed, 0) << "pixels changed other than by the sheet's transmittance";
}

TEST_P(TranslucentShadow, AnOpaqueCasterAboveTheGlassStillShadowsFully) {
  const auto [with_glass, map] = render(tinted_floor_and(glass("red_glass") + kBoxAbove));
  const Texels box_only = render(tinted_floor_and(kBoxAbove)).first;
  int black = 0;
  for (size_t p = 0; p < with_glass.rgba.size(); p += 4) {
    EXPECT_EQ(with_glass.rgba[p], box_only.rgba[p]) << "texel " << p / 4;  // red: not tinted where the box shadows
    if (box_only.rgba[p] == 0.0f) ++black;
  }
  EXPECT_GT(black, 20) << "the box's shadow";
  EXPECT_TRUE(all_one(map)) << "the sheet lies behind the box: not in the transmittance map";
}

// A receiver between the sheet and the sun (a box that casts no shadow, so the opaque map does
// not hide the sheet behind it) is not tinted: only what lies behind the nearest caster is.
// The sheet here is in the view (the scene pass does not draw it): every pixel the sheet
// changes with the box there is one it changes on the bare floor (its shadow), none on the box.
TEST_P(TranslucentShadow, AReceiverInFrontOfTheGlassIsNotTinted) {
  const std::string low_glass =
      R"(, { "shape": "plane", "size": [1, 1, 1], "material": "red_glass", "transform": { "translate": [0, 0.5, 0] } })";
  const std::string box_in_front = R"(, { "shape": "box", "size": [0.6, 0.6, 0.6], "material": "white", "cast_shadows": false,
                                          "transform": { "translate": [-1.3, 1.5, 0] } })";
  const Texels floor = render(tinted_floor_and("")).first;
  const Texels floor_glass = render(tinted_floor_and(low_glass)).first;
  const Texels box = render(tinted_floor_and(box_in_front)).first;
  const Texels box_glass = render(tinted_floor_and(low_glass + box_in_front)).first;
  auto differs = [](const Texels& a, const Texels& b, size_t p) {
    return a.rgba[p] != b.rgba[p] || a.rgba[p + 1] != b.rgba[p + 1] || a.rgba[p + 2] != b.rgba[p + 2];
  };
  int box_pixels = 0, tinted_elsewhere = 0;
  for (size_t p = 0; p < floor.rgba.size(); p += 4) {
    box_pixels += differs(floor, box, p) ? 1 : 0;
    tinted_elsewhere += differs(box, box_glass, p) && !differs(floor, floor_glass, p) ? 1 : 0;
  }
  EXPECT_GT(box_pixels, 4) << "the box in the view";
  EXPECT_EQ(tinted_elsewhere, 0) << "pixels tinted off the floor's shadow (the box)";
}

// No translucent caster: the map stays at 1 (the pass is not culled while the scene reads it)
// and the floor is bit for bit as the shadow map alone shades it.
TEST_P(TranslucentShadow, NoTranslucentCasterLeavesTheMapAtOne) {
  const auto [floor, map] = render(tinted_floor_and(kBoxAbove));
  const Texels plain = render(tinted_floor_and(kBoxAbove, false)).first;
  EXPECT_TRUE(all_one(map));
  EXPECT_EQ(floor.rgba, plain.rgba);
}

TEST_P(TranslucentShadow, StressStaysFinite) {
  const Texels floor = render(tinted_floor_and("")).first;
  for (const char* material : {"ior1", "ior4", "dark", "red_glass"}) {
    const auto [image, map] = render(tinted_floor_and(glass(material)));
    EXPECT_TRUE(all_finite(image)) << material;
    EXPECT_TRUE(all_finite(map)) << material;
  }
  // IOR 1, transmission 1, albedo 1: no interface, all light passes: the floor unchanged.
  EXPECT_EQ(render(tinted_floor_and(glass("ior1"))).first.rgba, floor.rgba);
  // Transmission 0 at coverage 0.999: 0.001 of the light passes.
  const Texels dark = render(tinted_floor_and(glass("dark"))).first;
  int dimmed = 0;
  for (size_t p = 0; p < floor.rgba.size(); p += 4) {
    if (dark.rgba[p] == floor.rgba[p]) continue;
    ++dimmed;
    EXPECT_NEAR(dark.rgba[p], 0.001 * floor.rgba[p], fp16_steps(floor.rgba[p]) * 1e-2 + 1e-5) << "texel " << p / 4;
  }
  EXPECT_GT(dimmed, 20);
}

// Against the CPU reference with its translucent shadow rays on (the default), by the
// translucency accuracy test's metric; what differs is the shadow edge (the map's texels).
TEST_P(TranslucentShadow, MatchesTheReference) {
  const Texels image = render(tinted_floor_and(glass("red_glass"))).first;
  reference::IntegrationSettings settings;
  settings.translucent_shadows = true;
  const reference::ReferenceImage truth = reference::render_image(reference::Renderer(scene_, settings), {image.width, image.height});
  double error = 0, total = 0;
  int off = 0;
  for (uint32_t j = 0; j < image.height; ++j) {
    for (uint32_t i = 0; i < image.width; ++i) {
      bool texel_off = false;
      for (size_t k = 0; k < 3; ++k) {
        const double gpu = image.rgba[4 * (j * image.width + i) + k], ref = truth.at(i, j)[k];
        error += std::abs(gpu - ref);
        total += ref;
        texel_off = texel_off || std::abs(gpu - ref) > 1e-2 * std::max(ref, 1e-2);
      }
      off += texel_off ? 1 : 0;
    }
  }
  std::printf("red glass shadow against the reference: relative mean error %.2e, %d of %u texels off by more than 1%%\n",
              error / total, off, image.width * image.height);
  EXPECT_LT(error / total, 2e-3);  // measured 6.4e-4 on lavapipe, both backends
  settings.translucent_shadows = false;  // the metric can fail: without them the reference's floor is black there
  const reference::ReferenceImage opaque = reference::render_image(reference::Renderer(scene_, settings), {image.width, image.height});
  double error_opaque = 0;
  for (uint32_t j = 0; j < image.height; ++j) {
    for (uint32_t i = 0; i < image.width; ++i) {
      for (size_t k = 0; k < 3; ++k) error_opaque += std::abs(image.rgba[4 * (j * image.width + i) + k] - opaque.at(i, j)[k]);
    }
  }
  EXPECT_GT(error_opaque / total, 2 * error / total);
}

INSTANTIATE_TEST_SUITE_P(Backends, TranslucentShadow, ::testing::ValuesIn(gpu_backends()),
                         [](const ::testing::TestParamInfo<Backend>& info) { return std::string(backend_name(info.param)); });

}  // namespace
}  // namespace volgraph::testing
