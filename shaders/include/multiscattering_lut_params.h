// atmosphere_multiscattering_lut.comp's parameters (passes/atmosphere/multiscattering_lut.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_MULTISCATTERING_LUT_PARAMS_H
#define VOLGRAPH_MULTISCATTERING_LUT_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(MultiscatteringLutParams) {
  ivec4 sampling;  // x: directions per axis, y: steps a ray
};
GPU_END

#endif  // VOLGRAPH_MULTISCATTERING_LUT_PARAMS_H
