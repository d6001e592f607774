// The aerial-perspective volumes' frame: atmosphere_aerial_perspective writes it to its lookup output for the passes that read the volumes, one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_AERIAL_LOOKUP_H
#define VOLGRAPH_AERIAL_LOOKUP_H
#include "gpu_struct.h"
#include "view_rays.h"

GPU_BEGIN
GPU_STRUCT(AerialLookup) {
  ViewRays view;  // the camera's rays; position.w its near plane, forward.w its far one
  vec4 volume;    // x: the distance the volume reaches (m), y: its slices
  vec4 sun;       // rgb: the sun's E at the top of the atmosphere (0 without a sun)
};
GPU_END

#endif  // VOLGRAPH_AERIAL_LOOKUP_H
