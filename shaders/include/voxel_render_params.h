// voxel_render's parameters (passes/voxels/voxel_render.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_VOXEL_RENDER_PARAMS_H
#define VOLGRAPH_VOXEL_RENDER_PARAMS_H
#include "gpu_struct.h"
#include "view_rays.h"

GPU_BEGIN
GPU_STRUCT(VoxelRenderParams) {
  ViewRays view;          // the camera's rays; position.w its near plane, forward.w its far one (m)
  vec4 light_direction;   // xyz toward the light (unit); w 1: the scene's sun, 0: a headlight of irradiance π
  vec4 light_irradiance;  // rgb E (W/m²)
  vec4 albedo;            // rgb the voxels' Lambertian albedo
};
GPU_END

#endif  // VOLGRAPH_VOXEL_RENDER_PARAMS_H
