// volume_phantom's parameters (passes/volume/volume_phantom.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_VOLUME_PHANTOM_PARAMS_H
#define VOLGRAPH_VOLUME_PHANTOM_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(VolumePhantomParams) {
  vec4 shape;     // x the radius, y the shell (ramp width), both fractions of the box
  ivec4 phantom;  // x VOLUME_PHANTOM_SPHERE or VOLUME_PHANTOM_SHELLS
};
GPU_END

#endif  // VOLGRAPH_VOLUME_PHANTOM_PARAMS_H
