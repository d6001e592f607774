// opacity_shadow_map.comp's parameters (passes/fog/opacity_shadow_map.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_OPACITY_PARAMS_H
#define VOLGRAPH_OPACITY_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(OpacityParams) {
  ivec4 steps;     // x: per layer, y: from the column's start toward the light, z: 1 deep layers (Yuksel & Keyser 2008), 0 regular
  vec4 distances;  // x: how far the march toward a directional light goes (m), y: the deep layers' spacing Δ (m)
};
GPU_END

#endif  // VOLGRAPH_OPACITY_PARAMS_H
