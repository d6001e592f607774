// The scene's lights packed for the GPU: the std140 mirror of LightList (and Light) in
// shaders/include/light_list.glsl (lighting.glsl), shared by every pass that lights something.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/lighting.h"

namespace volgraph::plumbing {

using physics::kMaxLights;

struct GpuLight {
  float position_type[4];        // xyz position, w type (0 directional, 1 point, 2 spot)
  float direction_cos_outer[4];  // xyz unit direction of travel, w cos(outer cone)
  float power_cos_inner[4];      // rgb irradiance or intensity, w cos(inner cone)
  static constexpr std::array<uint64_t, 3> offsets() {
    return {offsetof(GpuLight, position_type), offsetof(GpuLight, direction_cos_outer), offsetof(GpuLight, power_cos_inner)};
  }
};

struct GpuLightList {
  int32_t counts[4];
  GpuLight lights[kMaxLights];
  static constexpr std::array<uint64_t, 2> offsets() { return {offsetof(GpuLightList, counts), offsetof(GpuLightList, lights)}; }
};
static_assert(sizeof(GpuLightList) == 16 + 48 * kMaxLights);

// Throws std::logic_error past kMaxLights lights (the scene reader refuses such scenes).
GpuLightList pack_lights(const std::vector<Light>& lights);

}  // namespace volgraph::plumbing
