// voxel_render's face shading on the CPU: shaders/include/voxel_shading.h compiled as C++ with
// GLM's types, as voxel_overlap.h does with its header.
#pragma once

#include <glm/glm.hpp>

namespace volgraph::voxels::shading {

using namespace glm;

#include "shaders/include/voxel_shading.h"

}  // namespace volgraph::voxels::shading
