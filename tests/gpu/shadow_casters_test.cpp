// Which surfaces the shadow map draws (plumbing::Surfaces::shadow_casters): an object with
// cast_shadows false is left out, as the CPU reference leaves it out of its shadow rays,
// and so is a translucent one (its shadow is translucent_shadow_map's: translucent_shadow_map_test.cpp).
// A floor seen from above under a slanted sun, with a box above it (green albedo 0)
// whose shadow falls beside it: against the image without the box, a box that casts
// darkens floor pixels, one that does not changes only its own (magenta), and
// a translucent one (drawn by no pass here) changes nothing; an alpha-masked one is cut
// alike in the view and the shadow map.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

std::string floor_and(const std::string& box) {
  return R"({ "output": { "size": [32, 32] },
  "scene": { "camera": { "position": [0, 8, 0.01], "target": [0, 0, 0], "fov_y_deg": 30 },
    "background": { "radiance": [0, 0, 0] },
    "lights": [ { "type": "directional", "direction": [1, -1, 0], "irradiance": [3, 3, 3] } ],
    "materials": { "white": { "albedo": [1, 1, 1] }, "magenta": { "albedo": [1, 0, 1] }, "veil": { "albedo": [1, 0, 1], "alpha": 0.5 },
                   "cut": { "albedo": [1, 0, 1], "alpha": 0.3, "alpha_mode": "mask" }, "kept": { "albedo": [1, 0, 1], "alpha": 0.7, "alpha_mode": "mask" } },
    "objects": [ { "shape": "plane", "size": [20, 1, 20], "material": "white" } )" + box + R"( ] },
  "graph": { "passes": [
    { "name": "sun_shadow", "type": "shadow_map", "params": { "light": 0, "resolution": 512 } },
    { "name": "lit", "type": "scene", "inputs": { "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view" } } ],
    "outputs": ["lit.color"] } })";
}

std::string box(const std::string& material, bool casts) {
  return R"(, { "shape": "box", "size": [0.6, 0.6, 0.6], "material": ")" + material + R"(", "cast_shadows": )" +
         (casts ? "true" : "false") + R"(, "transform": { "translate": [-0.8, 0.8, 0] } })";
}

class ShadowCasters : public OnEachBackend<Backend> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  Texels render(const std::string& text) {
    const LoadedConfig loaded = load_config_text("shadow_casters.json", text, registry_);
    Scene scene = loaded.config.scene;
    Executor executor(device(), loaded.graph, &scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
};

// Pixels that differ from `floor`: {elsewhere (the floor shadowed: black, no ambient),
// on the box (lit magenta: red > 0, green 0)}.
std::array<int, 2> changed(const Texels& image, const Texels& floor) {
  std::array<int, 2> n{};
  for (size_t p = 0; p < image.rgba.size(); p += 4) {
    const bool same = image.rgba[p] == floor.rgba[p] && image.rgba[p + 1] == floor.rgba[p + 1] && image.rgba[p + 2] == floor.rgba[p + 2];
    if (!same) ++n[image.rgba[p] > 0 && image.rgba[p + 1] == 0 ? 1 : 0];
  }
  return n;
}

TEST_P(ShadowCasters, OnlyOpaqueObjectsThatCastShadowsAreInTheShadowMap) {
  const Texels floor = render(floor_and(""));
  const std::array<int, 2> casting = changed(render(floor_and(box("magenta", true))), floor);
  const std::array<int, 2> not_casting = changed(render(floor_and(box("magenta", false))), floor);
  const std::array<int, 2> translucent = changed(render(floor_and(box("veil", true))), floor);
  EXPECT_GT(casting[0], 4) << "the box's shadow on the floor";
  EXPECT_GT(casting[1], 4) << "the box itself";
  EXPECT_EQ(not_casting[0], 0) << "no shadow";
  EXPECT_EQ(not_casting[1], casting[1]) << "the same box";
  EXPECT_EQ(translucent[0] + translucent[1], 0);
}

// alphaMode mask: coverage below the cutoff (0.5) is a hole in the camera's view and in the
// shadow map alike (shadow_mask.frag); above it the box is drawn and casts as an opaque one.
TEST_P(ShadowCasters, MaskedTexelsBelowTheCutoffAreHolesInTheShadowMapToo) {
  const Texels floor = render(floor_and(""));
  const std::array<int, 2> opaque = changed(render(floor_and(box("magenta", true))), floor);
  const std::array<int, 2> cut = changed(render(floor_and(box("cut", true))), floor);
  const std::array<int, 2> kept = changed(render(floor_and(box("kept", true))), floor);
  EXPECT_EQ(cut[0], 0) << "no shadow";
  EXPECT_EQ(cut[1], 0) << "no box";
  EXPECT_EQ(kept[0], opaque[0]);
  EXPECT_EQ(kept[1], opaque[1]);
}

INSTANTIATE_TEST_SUITE_P(Backends, ShadowCasters, ::testing::ValuesIn(gpu_backends()),
                         [](const ::testing::TestParamInfo<Backend>& info) { return std::string(backend_name(info.param)); });

}  // namespace
}  // namespace volgraph::testing
