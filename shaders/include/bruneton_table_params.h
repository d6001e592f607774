// The Bruneton table steps' parameters (passes/atmosphere/bruneton_tables.cpp) and the table shape its readers (sky, aerial perspective) are given, one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_BRUNETON_TABLE_PARAMS_H
#define VOLGRAPH_BRUNETON_TABLE_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(BrunetonTableParams) {
  ivec4 size;   // the scattering table's nu, mu_s, mu, r texels
  ivec4 order;  // x: the scattering order of a table step; y: 1 when it is within the pass's orders; z: trapezoids along each ray (unused by the readers)
};
GPU_END

#endif  // VOLGRAPH_BRUNETON_TABLE_PARAMS_H
