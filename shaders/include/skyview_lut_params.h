// atmosphere_skyview_lut.comp's parameters (passes/atmosphere/skyview_lut.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_SKYVIEW_LUT_PARAMS_H
#define VOLGRAPH_SKYVIEW_LUT_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(SkyViewLutParams) {
  vec4 camera;    // x: radius, y: the sun's zenith cosine, z: 1 when there is a sun
  vec4 sampling;  // min samples, max samples, the length taking the max (m), multiple scattering (1)
  vec4 placement;  // x: where in its step each sample sits
};
GPU_END

#endif  // VOLGRAPH_SKYVIEW_LUT_PARAMS_H
