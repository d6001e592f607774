// The translucency pass's GPU tests' fixture: each backend × a variant of the pass (its
// name the parameter's second part), the built-in passes registered, a config rendered on
// the backend and its first output read; the case names "<backend>_<variant>". Shared by
// translucency_test.cpp, translucency_dispersion_test.cpp, translucency_dual_source_test.cpp
// and translucency_rough_test.cpp (its members are the fixture's, so the files a unity build
// batches together share no namespace-scope names).
#pragma once

#include <cstdio>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/scene/scene.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/config_on_each_backend.h"

namespace volgraph::testing {

class TranslucencyVariantFixture : public ConfigOnEachBackend<std::tuple<Backend, std::string>> {
 public:
  // A glass slab (IOR `ior`, `glass_extra` more material keys) turned 35° before a wall bright
  // on the left, dark on the right, `size` ("[W, H]") pixels, the pass's variant and
  // `refraction`, refracted_color a copy of the scene before it (the refraction and dispersion tests').
  static std::string slab_before_edge(const std::string& variant, const std::string& refraction, double ior,
                                      const std::string& glass_extra = "", const std::string& size = "[144, 96]") {
    char ior_text[32];
    std::snprintf(ior_text, sizeof ior_text, "%.17g", ior);
    return R"({ "output": { "size": )" + size + R"( },
  "scene": { "camera": { "position": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40 },
    "background": { "radiance": [0.2, 0.3, 0.4] },
    "materials": { "bright": { "albedo": [0, 0, 0], "emissive": [1, 1, 1] }, "dark": { "albedo": [0, 0, 0], "emissive": [0.1, 0.1, 0.1] },
                   "glass": { "albedo": [1, 1, 1], "transmission": 1, "volume": "solid", "ior": )" + ior_text + glass_extra + R"( } },
    "objects": [
      { "shape": "plane", "size": [10, 1, 20], "material": "bright", "transform": { "rotate_deg": [90, 0, 0], "translate": [-5, 0, -3] } },
      { "shape": "plane", "size": [10, 1, 20], "material": "dark", "transform": { "rotate_deg": [90, 0, 0], "translate": [5, 0, -3] } },
      { "shape": "box", "size": [5, 8, 0.5], "material": "glass", "transform": { "rotate_deg": [0, 35, 0] } } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "behind_glass", "type": "copy", "inputs": { "source": "lit.color" } },
    { "name": "glass", "type": "translucency", "variant": ")" + variant + R"(", "params": { "refraction": ")" + refraction + R"(" },
      "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame", "refracted_color": "behind_glass.copy" } } ],
    "outputs": ["glass.color"] } })";
  }

  static std::string case_name(const ::testing::TestParamInfo<std::tuple<Backend, std::string>>& info) {
    return std::string(backend_name(std::get<0>(info.param))) + "_" + std::get<1>(info.param);
  }

 protected:
  Backend backend() const override { return std::get<0>(GetParam()); }
  const std::string& variant() const { return std::get<1>(GetParam()); }
  // `path` names the config (its includes resolve against its folder); scene_ keeps its scene.
  Texels render(const std::string& text, const std::string& path = "translucency.json") { return render_outputs(path, text, 1).front(); }
};

}  // namespace volgraph::testing
