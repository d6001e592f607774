// A GPU test fixture on each backend that loads a config's text, runs one frame and reads its
// first output: what tests of one pass's output under a small hand-written graph share.
#pragma once

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "physics/translucency.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/config_on_each_backend.h"
#include "tests/support/image_compare.h"

namespace volgraph::testing {

// The red glass sheet (albedo (1, 0, 0), transmission 1, IOR 1.5; 1 m square at height 1.5
// around x = −1.5) over a white floor in a homogeneous fog (σt 0.05, albedo 1, g 0), the sun
// along (1, −1, 0): the scene of the translucent-fog tests, seen by `camera` at `size`.
inline std::string red_glass_in_fog(const std::string& size, const std::string& camera) {
  return R"("output": { "size": )" + size + R"( },
  "scene": { "camera": )" + camera + R"(,
    "background": { "radiance": [0, 0, 0] },
    "lights": [ { "type": "directional", "direction": [1, -1, 0], "irradiance": [3, 3, 3] } ],
    "materials": { "white": { "albedo": [1, 1, 1] }, "red_glass": { "albedo": [1, 0, 0], "transmission": 1, "ior": 1.5 } },
    "objects": [ { "shape": "plane", "size": [20, 1, 20], "material": "white" },
                 { "shape": "plane", "size": [1, 1, 1], "material": "red_glass", "transform": { "translate": [-1.5, 1.5, 0] } } ],
    "media": { "fog": { "albedo": [1, 1, 1], "extinction": [0.05, 0.05, 0.05], "g": 0 } } })";
}

// A `translucent_shadow_map` named "tint" over `sun_shadow` (a graph pass, with its comma),
// and the two inputs that read it; both empty when not `tinted`.
inline std::string tint_pass(bool tinted) {
  return tinted ? R"({ "name": "tint", "type": "translucent_shadow_map", "params": { "resolution": 512 },
             "inputs": { "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view" } },)"
                : "";
}
inline std::string tint_inputs(bool tinted) {
  return tinted ? R"(, "translucent_shadow": "tint.transmittance", "translucent_shadow_depth": "tint.depth")" : "";
}

// The red sheet's transmittance for the sun of red_glass_in_fog: its normal +y, the sun 45°
// off it, (1 − F)·ρ with one interface (ρ red = 1).
inline double red_glass_transmittance() { return 1.0 - physics::interface_reflectance(1.5, std::sqrt(0.5)); }

// `tinted` (with the sheet's translucent shadow) against `plain` (without), texel by texel:
// each texel that changed is one behind the red sheet as the sun sees it — red exactly
// red_glass_transmittance() × plain's (two fp16 steps), green and blue 0 — and at least
// `at_least` texels (`what`) are. Every other texel is bit for bit plain's.
inline void expect_tinted_by_red_glass(const Texels& plain, const Texels& tinted, int at_least, const std::string& what) {
  ASSERT_EQ(plain.rgba.size(), tinted.rgba.size());
  const double red = red_glass_transmittance();
  int behind = 0, otherwise_changed = 0;
  for (size_t p = 0; p < plain.rgba.size(); p += 4) {
    const bool same = plain.rgba[p] == tinted.rgba[p] && plain.rgba[p + 1] == tinted.rgba[p + 1] && plain.rgba[p + 2] == tinted.rgba[p + 2];
    if (same) continue;
    if (tinted.rgba[p + 1] != 0.0f || tinted.rgba[p + 2] != 0.0f || plain.rgba[p + 1] <= 0.0f) {
      ++otherwise_changed;
      continue;
    }
    ++behind;
    EXPECT_NEAR(tinted.rgba[p], red * plain.rgba[p], fp16_steps(red * plain.rgba[p])) << what << " " << p / 4;
  }
  EXPECT_GT(behind, at_least) << what << "s behind the sheet";
  EXPECT_EQ(otherwise_changed, 0) << what << "s changed other than by the sheet's transmittance";
}

class ConfigOutputOnEachBackend : public ConfigOnEachBackend<Backend> {
 protected:
  Backend backend() const override { return GetParam(); }
  // The config's first graph output after one frame (`name` names the text in messages).
  Texels first_output(const std::string& name, const std::string& text) { return render_outputs(name, text, 1).front(); }
};

}  // namespace volgraph::testing
