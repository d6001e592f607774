// cloud_temporal.comp's own block (passes/clouds/cloud_temporal.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_CLOUD_TEMPORAL_PARAMS_H
#define VOLGRAPH_CLOUD_TEMPORAL_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(CloudTemporalBlock) {
  ivec4 block;  // x the march's update_block, yz the pixel of each block it marched this frame (Bayer order)
  vec4 depth;   // x 1: reproject at the clouds' depth, 0: at the far plane
};
GPU_END

#endif  // VOLGRAPH_CLOUD_TEMPORAL_PARAMS_H
