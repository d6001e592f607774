// voxel_render's parameters (passes/voxels/voxel_render.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_VOXEL_RENDER_PARAMS_H
#define VOLGRAPH_VOXEL_RENDER_PARAMS_H
#include "gpu_struct.h"
#include "view_rays.h"

// The variants' codes (params.variant.x): dda casts rays in the compute step; faces' compute
// step only lays the scene behind (colour, hit 0) and its graphics step draws the quads over it.
#define VOXEL_RENDER_DDA 0
#define VOXEL_RENDER_FACES 1
#define VOXEL_RENDER_MARCHING_CUBES 2  // as faces: the compute step lays the scene, the graphics step draws the surface

GPU_BEGIN
GPU_STRUCT(VoxelRenderParams) {
  ViewRays view;          // the camera's rays; position.w its near plane, forward.w its far one (m)
  mat4 view_projection;   // world to clip space, as the scene pass draws (faces' quads, marching_cubes' triangles)
  vec4 light_direction;   // xyz toward the light (unit); w 1: the scene's sun, 0: a headlight of irradiance π
  vec4 light_irradiance;  // rgb E (W/m²)
  vec4 albedo;            // rgb the voxels' Lambertian albedo
  ivec4 variant;          // x VOXEL_RENDER_DDA, VOXEL_RENDER_FACES or VOXEL_RENDER_MARCHING_CUBES
};
GPU_END

#endif  // VOLGRAPH_VOXEL_RENDER_PARAMS_H
