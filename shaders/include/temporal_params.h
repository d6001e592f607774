// The temporal passes' parameters (passes/fog/temporal.h; froxel_temporal.comp, pixel_temporal.comp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_TEMPORAL_PARAMS_H
#define VOLGRAPH_TEMPORAL_PARAMS_H
#include "gpu_struct.h"
#include "view_rays.h"

GPU_BEGIN
GPU_STRUCT(TemporalParams) {
  ViewRays previous_view;  // the camera of the frame the history holds
  vec4 blend;              // x: alpha (weight of a new frame), y: 1 when the history holds the last frame,
                           // z: 1 to reproject, 0 to read the history at the same froxel
};
GPU_END

#endif  // VOLGRAPH_TEMPORAL_PARAMS_H
