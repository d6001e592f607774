#version 450
#extension GL_GOOGLE_include_directive : require
// voxelize, variant six_view_depth (passes/voxels/voxelize.cpp): the object's triangles (grid
// coordinates, the compute variant's corners buffer as the vertex buffer) into one of the six
// orthographic depth views (include/six_view_depth.glsl); depth only, no fragment shader.
#include "include/voxelize_params.h"
#include "include/six_view_depth.glsl"

layout(set = 0, binding = 0) uniform VoxelizeParamsBlock { VoxelizeParams params; };

layout(location = 0) in vec3 corner;

void main() { gl_Position = six_view_clip(corner, params.counts.z, float(params.counts.y)); }
