// Scene fragments (JSON text) shared by the fog technique tests.
#pragma once

#include <string>

namespace volgraph::testing {

// A fog layer (y 0–2, σs 0.5) and, with `box`, a dense absorber over x < 0 above it
// (σa 0.1, 10 m tall: transmittance e^(−1) straight up), lit from straight above.
inline std::string layer_under_box_media(bool box) {
  const std::string layer = R"({ "shape": "box", "size": [20, 2, 4], "sigma_s": [0.5, 0.5, 0.5], "sigma_a": [0, 0, 0],
                                 "transform": { "translate": [0, 1, -2] } })";
  const std::string dense = R"(, { "shape": "box", "size": [10, 10, 40], "sigma_s": [0, 0, 0], "sigma_a": [0.1, 0.1, 0.1],
                                   "transform": { "translate": [-5, 8, -2] } })";
  return R"({ "volumes": [ )" + layer + (box ? dense : "") + " ] }";
}
inline const char* kLightFromAbove =
    R"([ { "type": "directional", "direction": [0, -1, 0], "irradiance": [3, 3, 3], "cast_shadows": false } ])";
inline const char* kCameraAtTheLayer = R"({ "position": [0, 1, 5], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 100 })";

// The fog tests' stress media (σt 1e4, σs 1e-7 with a zero-size volume, a height fog
// 1 km down with falloff 1000; g ±0.999) and lights (a point light at the camera's
// height, a directional one).
inline const char* const kStressMedia[] = {
    R"({ "fog": { "sigma_s": [1e4, 1e4, 1e4], "sigma_a": [0, 0, 0], "g": 0.999 } })",
    R"({ "fog": { "sigma_s": [1e-7, 1e-7, 1e-7], "sigma_a": [0, 0, 0], "g": -0.999 },
        "volumes": [ { "shape": "sphere", "size": [0, 0, 0], "sigma_s": [5, 5, 5] } ] })",
    R"({ "height_fog": { "sigma_s": [1, 1, 1], "sigma_a": [0.5, 0.5, 0.5], "g": 0.999, "base_height": -1000, "falloff": 1000 } })",
};
inline const char* kStressLights = R"([ { "type": "directional", "direction": [0, 0, -1], "irradiance": [10, 10, 10] },
                                        { "type": "point", "position": [0, 1, 0], "intensity": [1e4, 1e4, 1e4] } ])";

}  // namespace volgraph::testing
