// depth_fog.comp's parameters (passes/fog/depth_fog.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_DEPTH_FOG_PARAMS_H
#define VOLGRAPH_DEPTH_FOG_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(DepthFogParams) {
  vec4 fog;    // x start (m), y end (m), z density (1/m), w variant: DEPTH_FOG_* (include/depth_fog_codes.h)
  vec4 color;  // rgb fog radiance
};
GPU_END

#endif  // VOLGRAPH_DEPTH_FOG_PARAMS_H
