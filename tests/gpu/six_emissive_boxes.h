// The scene the cube-map tests look around in (scene_probe_test.cpp, cube_mips_test.cpp): six
// emissive boxes (albedo 0: their radiance is their emission exactly) 3 m from (0, 1, 0)
// along ±x, ±y, ±z, each its own colour — red, green, blue, yellow, cyan, magenta in the
// faces' order — as JSON fragments of a config's "materials" and "objects".
#pragma once

#include <string>

namespace volgraph::testing {

inline std::string six_emissive_box_materials() {
  return R"("px": { "albedo": [0, 0, 0], "emissive": [1, 0, 0] }, "nx": { "albedo": [0, 0, 0], "emissive": [0, 1, 0] },
      "py": { "albedo": [0, 0, 0], "emissive": [0, 0, 1] }, "ny": { "albedo": [0, 0, 0], "emissive": [1, 1, 0] },
      "pz": { "albedo": [0, 0, 0], "emissive": [0, 1, 1] }, "nz": { "albedo": [0, 0, 0], "emissive": [1, 0, 1] })";
}

inline std::string six_emissive_box_objects() {
  return R"({ "shape": "box", "size": [0.2, 1, 1], "material": "px", "transform": { "translate": [3, 1, 0] } },
      { "shape": "box", "size": [0.2, 1, 1], "material": "nx", "transform": { "translate": [-3, 1, 0] } },
      { "shape": "box", "size": [1, 0.2, 1], "material": "py", "transform": { "translate": [0, 4, 0] } },
      { "shape": "box", "size": [1, 0.2, 1], "material": "ny", "transform": { "translate": [0, -2, 0] } },
      { "shape": "box", "size": [1, 1, 0.2], "material": "pz", "transform": { "translate": [0, 1, 3] } },
      { "shape": "box", "size": [1, 1, 0.2], "material": "nz", "transform": { "translate": [0, 1, -3] } })";
}

}  // namespace volgraph::testing
