// The scene's lights packed for the GPU: the std140 mirror of LightList in
// shaders/include/light_list.glsl, shared by every pass that lights something.
#pragma once

#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"

namespace volgraph::shading {

constexpr int kMaxLights = 16;  // MAX_LIGHTS in light_list.glsl

struct GpuLight {
  float position_type[4];        // xyz position, w type (0 directional, 1 point, 2 spot)
  float direction_cos_outer[4];  // xyz unit direction of travel, w cos(outer cone)
  float power_cos_inner[4];      // rgb irradiance or intensity, w cos(inner cone)
};

struct GpuLightList {
  int32_t counts[4];
  GpuLight lights[kMaxLights];
};
static_assert(sizeof(GpuLightList) == 16 + 48 * kMaxLights);

// Throws DeviceError (unsupported) past kMaxLights lights.
GpuLightList pack_lights(const std::vector<Light>& lights);

}  // namespace volgraph::shading
