// The camera's rays by NDC (view_rays.glsl; C++ fills them in passes/fog/fog_frame.cpp pack_view_rays), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_VIEW_RAYS_H
#define VOLGRAPH_VIEW_RAYS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(ViewRays) {
  vec4 position;  // xyz; w unused
  vec4 forward;
  vec4 right;     // scaled by tan(fov/2)·aspect
  vec4 up;        // scaled by tan(fov/2)
};
GPU_END

#endif  // VOLGRAPH_VIEW_RAYS_H
