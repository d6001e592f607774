// The phase table's parameterisation on the CPU: shaders/include/cloud_phase_table.h
// compiled as C++ with GLM's types (as physics/cloud_lighting.h does).
#pragma once

#include <glm/glm.hpp>

namespace volgraph::physics::cloud_phase_table {

using namespace glm;

#include "shaders/include/cloud_phase_table.h"

}  // namespace volgraph::physics::cloud_phase_table
