// The cloud noises on the CPU: shaders/include/cloud_noise.h compiled as C++ with GLM's
// vector types, so the twin is the shader's own text (Bruneton 2017's functions.glsl
// pattern): float arithmetic, the same hash, the same texels to rounding.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace volgraph::physics::cloud_noise {

using namespace glm;
using uint = uint32_t;

#include "shaders/include/cloud_noise.h"

}  // namespace volgraph::physics::cloud_noise
