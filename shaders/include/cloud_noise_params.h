// cloud_noise's parameters (passes/clouds/cloud_noise.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_CLOUD_NOISE_PARAMS_H
#define VOLGRAPH_CLOUD_NOISE_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(CloudNoiseParams) {
  uvec4 seed;  // x: the seed
};
GPU_END

#endif  // VOLGRAPH_CLOUD_NOISE_PARAMS_H
