// The shadow map's light view (passes/shadow_map.cpp writes it; every reader holds it as its block's one member), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_SHADOW_VIEW_H
#define VOLGRAPH_SHADOW_VIEW_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(ShadowView) {
  mat4 light_view_projection;  // world → the shadow map's clip space
  mat4 clip_to_world;          // its inverse: NDC (x, y, depth in [0, 1], 1) → world
  vec4 params;                 // x depth bias (normalised depth), y PCF radius (texels), w shadowed light index
  ivec4 mode;                  // x: 1 PCF, 0 one tap
};
GPU_END

#endif  // VOLGRAPH_SHADOW_VIEW_H
