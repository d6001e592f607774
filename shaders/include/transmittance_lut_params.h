// atmosphere_transmittance_lut.comp's parameters (passes/atmosphere/transmittance_lut.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_TRANSMITTANCE_LUT_PARAMS_H
#define VOLGRAPH_TRANSMITTANCE_LUT_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(TransmittanceLutParams) {
  ivec4 panels;  // x: Gauss–Legendre panels along each ray
};
GPU_END

#endif  // VOLGRAPH_TRANSMITTANCE_LUT_PARAMS_H
