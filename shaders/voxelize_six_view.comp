#version 450
#extension GL_GOOGLE_include_directive : require
// voxelize, variant six_view_depth (passes/voxels/voxelize.cpp): a voxel is solid when its
// centre lies between the nearest surfaces the + and − views see along all three axes
// (Karabassi et al. 1999; include/six_view_depth.glsl). r 1 where solid, else 0; each voxel
// written once.
#include "include/voxelize_params.h"
#include "include/six_view_depth.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(set = 0, binding = 0) uniform VoxelizeParamsBlock { VoxelizeParams params; };
layout(set = 0, binding = 1) uniform texture2D view_x_plus;
layout(set = 0, binding = 2) uniform texture2D view_x_minus;
layout(set = 0, binding = 3) uniform texture2D view_y_plus;
layout(set = 0, binding = 4) uniform texture2D view_y_minus;
layout(set = 0, binding = 5) uniform texture2D view_z_plus;
layout(set = 0, binding = 6) uniform texture2D view_z_minus;
layout(set = 0, binding = 7) uniform sampler nearest;
layout(set = 0, binding = 8, rgba8) uniform writeonly image3D voxels;

// View `view`'s depth at `texel` (views as include/six_view_depth.glsl numbers them).
float view_depth(int view, ivec2 texel) {
  switch (view) {
    case 0: return texelFetch(sampler2D(view_x_plus, nearest), texel, 0).r;
    case 1: return texelFetch(sampler2D(view_x_minus, nearest), texel, 0).r;
    case 2: return texelFetch(sampler2D(view_y_plus, nearest), texel, 0).r;
    case 3: return texelFetch(sampler2D(view_y_minus, nearest), texel, 0).r;
    case 4: return texelFetch(sampler2D(view_z_plus, nearest), texel, 0).r;
    default: return texelFetch(sampler2D(view_z_minus, nearest), texel, 0).r;
  }
}

void main() {
  const ivec3 voxel = ivec3(gl_GlobalInvocationID.xyz);
  const int n = params.counts.y;
  if (any(greaterThanEqual(voxel, ivec3(n)))) return;
  bool inside = true;
  for (int axis = 0; axis < 3; ++axis) {
    const ivec2 texel = six_view_texel(voxel, axis);
    const float along = (float(voxel[axis]) + 0.5) / float(n);
    inside = inside && six_view_inside_along(along, view_depth(2 * axis, texel), view_depth(2 * axis + 1, texel));
  }
  imageStore(voxels, voxel, vec4(inside ? 1.0 : 0.0, 0.0, 0.0, 0.0));
}
