// atmosphere_aerial_perspective's frame (passes/atmosphere/aerial_perspective.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_AERIAL_PERSPECTIVE_FRAME_H
#define VOLGRAPH_AERIAL_PERSPECTIVE_FRAME_H
#include "gpu_struct.h"
#include "view_rays.h"

GPU_BEGIN
GPU_STRUCT(AerialPerspectiveFrame) {
  ViewRays view;
  vec4 planet_up;   // xyz: the camera's zenith, w: its radius
  vec4 toward_sun;  // xyz: toward the sun, w: its zenith cosine at the camera
  vec4 volume;      // x: metres a slice, y: 1 when there is a sun
  vec4 sampling;    // min and max samples, the length taking the max (m), where in its step a sample sits
};
GPU_END

#endif  // VOLGRAPH_AERIAL_PERSPECTIVE_FRAME_H
