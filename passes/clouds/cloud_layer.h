// What every cloud pass takes from the scene the same way: the sun the layer is lit by,
// the planet it lies on and where the wind has carried it at a frame. One text, so the
// clouds, their shadows and their march agree.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "graph/scene/scene.h"

namespace volgraph::clouds {

constexpr double kEarthRadius = 6360e3;   // m: the planet without an atmosphere (DESIGN.md's units)
constexpr double kFramesPerSecond = 60;   // the wind's clock: the graph has frames, not seconds

// The layer's sun: the scene's (Scene::sun_light).
inline int sun_index(const Scene& scene) { return scene.sun_light(); }

// The planet's radius (m): the atmosphere's ground, else Earth's.
inline double planet_radius(const Scene& scene) { return scene.atmosphere ? scene.atmosphere->bottom_radius : kEarthRadius; }

// The altitude of world y = 0 (m): the atmosphere's origin, else the ground.
inline double origin_altitude(const Scene& scene) { return scene.atmosphere ? scene.atmosphere->origin_altitude : 0; }

// How far the wind has carried the layer at `frame` (m).
inline std::array<double, 3> wind_offset(const CloudLayer& layer, uint64_t frame) {
  const double seconds = double(frame) / kFramesPerSecond;
  return {layer.wind[0] * seconds, layer.wind[1] * seconds, layer.wind[2] * seconds};
}

}  // namespace volgraph::clouds
