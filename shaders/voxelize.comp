#version 450
#extension GL_GOOGLE_include_directive : require
// voxelize (passes/voxels/voxelize.cpp): one invocation per voxel, looping over every
// triangle (grid coordinates, three corners each) with Akenine-Möller's conservative overlap
// test (shaders/include/voxel_overlap.h, the CPU twin's text); r 1 where any overlaps, else 0.
// Each voxel is written once, so no clear and no atomics are needed.
#include "include/voxelize_params.h"
#include "include/voxel_overlap.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform VoxelizeParamsBlock { VoxelizeParams params; };
layout(set = 0, binding = 1, std430) readonly buffer Corners { vec4 corners[]; };
layout(set = 0, binding = 2, rgba8) uniform writeonly image3D voxels;

void main() {
  const ivec3 voxel = ivec3(gl_GlobalInvocationID.xyz);
  if (any(greaterThanEqual(voxel, ivec3(params.counts.y)))) return;
  float filled = 0.0;
  for (int t = 0; t < params.counts.x && filled == 0.0; ++t) {
    if (voxel_overlaps(voxel, corners[3 * t].xyz, corners[3 * t + 1].xyz, corners[3 * t + 2].xyz)) filled = 1.0;
  }
  imageStore(voxels, voxel, vec4(filled, 0.0, 0.0, 0.0));
}
