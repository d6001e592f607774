// A light as passes receive it (std140; C++ packs it in passes/plumbing/light_list.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_LIGHT_H
#define VOLGRAPH_LIGHT_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(Light) {
  vec4 position_type;        // xyz position (point, spot), w type
  vec4 direction_cos_outer;  // xyz direction the light travels (directional, spot), w cos(outer cone)
  vec4 power_cos_inner;      // rgb irradiance (directional, W/m²) or intensity (point, spot, W/sr); w cos(inner cone)
};
GPU_END

#endif  // VOLGRAPH_LIGHT_H
