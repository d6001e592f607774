#version 450
#extension GL_GOOGLE_include_directive : require
// voxel_render, variant faces (passes/voxels/voxel_render.cpp): the cube-face quads, in world
// space, to clip space by the scene pass's view-projection.
#include "include/voxel_render_params.h"

layout(set = 0, binding = 0) uniform VoxelRenderParamsBlock { VoxelRenderParams params; };

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
// The quad's plane: xyz its outward normal (an axis), w its coordinate along that axis (m).
layout(location = 0) flat out vec4 face_plane;

void main() {
  face_plane = vec4(normal, dot(normal, position));
  gl_Position = params.view_projection * vec4(position, 1.0);
}
