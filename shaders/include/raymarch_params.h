// raymarch_fog's parameters (passes/fog/raymarch_fog.cpp; raymarch_fog_body.glsl), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_RAYMARCH_PARAMS_H
#define VOLGRAPH_RAYMARCH_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(RaymarchParams) {
  ivec4 steps;      // x: steps along the view ray, y: steps toward each light (0: no volumetric shadows)
  vec4 distances;   // x: max_distance (view depth, m) where no surface is, y: shadow_distance (m) toward directional lights
  vec4 jitter;      // x: 1 jittered samples, 0 each step's midpoint; y: the frame
  ivec4 modes;      // x: the phase code (phase_codes.h)
  vec4 lobes;       // dual-lobe HG: x backward g, y forward weight
};
GPU_END

#endif  // VOLGRAPH_RAYMARCH_PARAMS_H
