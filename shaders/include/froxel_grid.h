// The froxel grid's size and depth range (froxel.glsl), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_FROXEL_GRID_H
#define VOLGRAPH_FROXEL_GRID_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(FroxelGrid) {
  uvec4 size;   // xyz froxels, w unused
  vec4 range;   // x near, y far (view depth, m), z distribution (0 linear, 1 exponential)
};
GPU_END

#endif  // VOLGRAPH_FROXEL_GRID_H
