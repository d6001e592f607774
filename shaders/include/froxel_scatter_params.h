// froxel_scatter's parameters (passes/fog/froxel_scatter.cpp; froxel_scatter_body.glsl), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_FROXEL_SCATTER_PARAMS_H
#define VOLGRAPH_FROXEL_SCATTER_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(FroxelScatterParams) {
  ivec4 modes;  // x: the phase code (phase_codes.h); y: 1 skips froxels without scattering
  vec4 lobes;   // dual-lobe HG: x backward g, y forward weight
  vec4 volumetric;  // volumetric self-shadowing: x steps toward each light (0: off), y distance (m)
};
GPU_END

#endif  // VOLGRAPH_FROXEL_SCATTER_PARAMS_H
