// vignette.comp's parameters (passes/post/vignette.cpp), one text for GLSL and C++
// (gpu_struct.h).
#ifndef VOLGRAPH_VIGNETTE_PARAMS_H
#define VOLGRAPH_VIGNETTE_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(VignetteParams) {
  vec4 lens;  // x tan(fov_y / 2), y the aspect (width / height), z strength
};
GPU_END

#endif  // VOLGRAPH_VIGNETTE_PARAMS_H
