// A GPU test fixture on each backend that loads a config's text, runs one frame and reads its
// first output: what tests of one pass's output under a small hand-written graph share.
#pragma once

#include <string>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

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

class ConfigOutputOnEachBackend : public OnEachBackend<Backend> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  // The config's first graph output after one frame (`name` names the text in messages).
  Texels first_output(const std::string& name, const std::string& text) {
    const LoadedConfig loaded = load_config_text(name, text, registry_);
    scene_ = loaded.config.scene;
    Executor executor(device(), loaded.graph, &scene_, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
  Scene scene_;
};

}  // namespace volgraph::testing
