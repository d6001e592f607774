// The cloud layer's density on the CPU: shaders/include/cloud_density.h compiled as C++ with
// GLM's vector types, as physics/cloud_noise.h does, so the twin is the shader's own text.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace volgraph::physics::cloud_density {

using namespace glm;
using uint = uint32_t;

#include "shaders/include/cloud_density.h"

}  // namespace volgraph::physics::cloud_density
