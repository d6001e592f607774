// scatter_integrate.comp's parameters (passes/fog/scatter_integrate.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_INTEGRATE_PARAMS_H
#define VOLGRAPH_INTEGRATE_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(IntegrateParams) {
  ivec4 method;  // x: INTEGRATE_WRONSKI or INTEGRATE_HILLAIRE
};
GPU_END

#endif  // VOLGRAPH_INTEGRATE_PARAMS_H
