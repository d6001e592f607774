// voxelize's parameters (passes/voxels/voxelize.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_VOXELIZE_PARAMS_H
#define VOLGRAPH_VOXELIZE_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(VoxelizeParams) {
  ivec4 counts;  // x the triangles, y the grid's resolution; six_view_depth's views: z the view (0…5, include/six_view_depth.glsl)
};
GPU_END

#endif  // VOLGRAPH_VOXELIZE_PARAMS_H
