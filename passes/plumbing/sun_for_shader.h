// The scene's sun (Scene::sun_light(): the atmosphere's, else the first directional light) as
// the lit-surface shaders of volume_visualize and voxel_render take it: xyz the unit vector
// toward it and w 1, rgb its irradiance (W/m²); w 0 and nothing else without a sun (their
// shaders light by a headlight then).
#pragma once

#include <cmath>
#include <cstddef>

#include "graph/scene/scene.h"
#include "shaders/include/gpu_struct.h"

namespace volgraph::plumbing {

inline void write_sun_for_shader(const Scene& scene, gpu::vec4& toward_light, gpu::vec4& irradiance) {
  const int sun = scene.sun_light();
  if (sun < 0) return;
  const Light& light = scene.lights[size_t(sun)];
  const double n = std::sqrt(light.direction[0] * light.direction[0] + light.direction[1] * light.direction[1] +
                             light.direction[2] * light.direction[2]);
  for (int i = 0; i < 3; ++i) {
    toward_light[i] = float(-light.direction[size_t(i)] / n);
    irradiance[i] = float(light.irradiance[size_t(i)]);
  }
  toward_light[3] = 1;
}

}  // namespace volgraph::plumbing
