// The procedural phantoms on the CPU: shaders/include/volume_phantom.h compiled as C++ with
// GLM's types, as physics/cloud_density.h does with its header.
#pragma once

#include <glm/glm.hpp>

namespace volgraph::physics::volume_phantom {

using namespace glm;

#include "shaders/include/volume_phantom.h"

}  // namespace volgraph::physics::volume_phantom
