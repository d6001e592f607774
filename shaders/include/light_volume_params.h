// light_volume's parameters (passes/fog/light_volume.cpp), the one member of its shaders' Params block, one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_LIGHT_VOLUME_PARAMS_H
#define VOLGRAPH_LIGHT_VOLUME_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(LightVolumeParams) {
  mat4 camera_clip;  // world → the camera's clip space: w the view depth, near plane 1e-3·near, no far plane
  ivec4 sizes;       // x: cells per side of the grid over the shadow map; z, w: the fog images' width and height
};
GPU_END

#endif  // VOLGRAPH_LIGHT_VOLUME_PARAMS_H
