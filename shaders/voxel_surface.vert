#version 450
#extension GL_GOOGLE_include_directive : require
// voxel_render, variant marching_cubes (passes/voxels/voxel_render.cpp): the extracted surface's
// triangles, in world space, to clip space by the scene pass's view-projection; position and
// normal (the field's gradient) interpolated.
#include "include/voxel_render_params.h"

layout(set = 0, binding = 0) uniform VoxelRenderParamsBlock { VoxelRenderParams params; };

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 surface_normal;

void main() {
  world_position = position;
  surface_normal = normal;
  gl_Position = params.view_projection * vec4(position, 1.0);
}
