// voxelize's grid placement (passes/voxels/voxelize.cpp, output `grid`), one text for GLSL and
// C++ (gpu_struct.h): voxel (i, j, k) is the world box origin + [i, i+1]·size × … .
#ifndef VOLGRAPH_VOXEL_GRID_H
#define VOLGRAPH_VOXEL_GRID_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(VoxelGrid) {
  vec4 origin;      // xyz the grid's lowest corner (m), w the voxel's side (m)
  ivec4 resolution; // x the voxels along each axis (a cube)
};
GPU_END

#endif  // VOLGRAPH_VOXEL_GRID_H
