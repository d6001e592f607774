// The triangle–voxel overlap test on the CPU: shaders/include/voxel_overlap.h compiled as C++
// with GLM's types, as physics/volume_phantom.h does with its header.
#pragma once

#include <glm/glm.hpp>

namespace volgraph::voxels::overlap {

using namespace glm;

#include "shaders/include/voxel_overlap.h"

}  // namespace volgraph::voxels::overlap
