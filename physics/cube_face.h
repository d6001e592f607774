// A cube map's faces and directions on the CPU: shaders/include/cube_face.h compiled as
// C++ with GLM's types (as physics/cloud_phase_table.h does).
#pragma once

#include <glm/glm.hpp>

namespace volgraph::physics::cube {

using namespace glm;

#include "shaders/include/cube_face.h"

}  // namespace volgraph::physics::cube
