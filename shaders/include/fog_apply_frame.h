// fog_apply's frame (passes/fog/fog_apply.cpp; fog_image_lookup*.glsl), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_FOG_APPLY_FRAME_H
#define VOLGRAPH_FOG_APPLY_FRAME_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(FogApplyFrame) {
  vec4 size;  // xy: the colour's size in pixels; z, w: the camera's near, far (m) (the depth-aware lookup)
};
GPU_END

#endif  // VOLGRAPH_FOG_APPLY_FRAME_H
