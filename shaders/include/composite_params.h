// composite.comp's parameters (passes/composite.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_COMPOSITE_PARAMS_H
#define VOLGRAPH_COMPOSITE_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(CompositeParams) {
  uvec2 size;
  float exposure_ev;
  int tone_map_op;
};
GPU_END

#endif  // VOLGRAPH_COMPOSITE_PARAMS_H
