// The sky pass's frame (passes/atmosphere/sky.cpp), the one member of every sky variant's Frame block, one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_SKY_PASS_FRAME_H
#define VOLGRAPH_SKY_PASS_FRAME_H
#include "gpu_struct.h"
#include "view_rays.h"

GPU_BEGIN
GPU_STRUCT(SkyPassFrame) {
  ViewRays view;
  vec4 planet_up;   // xyz: the camera's zenith, w: its radius clamped to the top (the sky-view LUT's)
  vec4 toward_sun;  // xyz: toward the sun, w: its zenith cosine at the camera
  vec4 sun;         // rgb: E, w: 1 when there is a sun
  vec4 sun_disk;    // x: angular radius, y: 1 to draw the disk, z: 1 to limb-darken it, w: 1 to draw the ground
  vec4 camera;      // x: the camera's radius as it is (m), y: 1 for the multiple-scattering term
  vec4 sampling;    // min and max samples a ray, the length taking the max (m), where in its step each sample sits
};
GPU_END

#endif  // VOLGRAPH_SKY_PASS_FRAME_H
