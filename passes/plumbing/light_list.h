// The scene's lights packed for the GPU: gpu::LightList and gpu::Light, written once for
// GLSL and C++ (shaders/include/light_list.h, light.h), shared by every pass that lights something.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/lighting.h"
#include "shaders/include/light_list.h"

namespace volgraph::plumbing {

using physics::kMaxLights;

static_assert(GPU_MAX_LIGHTS == kMaxLights, "shaders/include/light_list.h and physics/lighting.h name one limit");
static_assert(sizeof(gpu::LightList) == 16 + 48 * kMaxLights);

// Throws std::logic_error past kMaxLights lights (the scene reader refuses such scenes).
gpu::LightList pack_lights(const std::vector<Light>& lights);

}  // namespace volgraph::plumbing
