// cloud_march.comp's parameters (passes/clouds/cloud_march.cpp), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_CLOUD_MARCH_PARAMS_H
#define VOLGRAPH_CLOUD_MARCH_PARAMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(CloudMarchParams) {
  vec4 view_position;   // xyz the camera; w its near plane (m)
  vec4 view_forward;    // view_rays.glsl's rays; w the far plane (m)
  vec4 view_right;
  vec4 view_up;
  vec4 sun;             // xyz toward the sun (unit); w 1 with a sun, 0 without
  vec4 sun_irradiance;  // rgb W/m² on a surface facing the sun
  vec4 ambient;         // rgb ambient radiance (W/(m²·sr)) the cloud scatters
  vec4 layer;           // x bottom altitude, y top altitude, z planet radius, w the altitude of world y = 0 (m)
  vec4 cloud;           // x coverage, y type, z extinction (1/m at density 1), w max_distance (m)
  vec4 scales;          // x shape tile, y detail tile (m), z curl distortion (detail tiles), w light march length (m)
  vec4 wind;            // xyz the noise's offset (m): wind × time; w the frame index mod 64 (the jitter's)
  vec4 weather;         // the weather map's lookup (cloud_layer.glsl): x 1 / its size (1/m), yz its offset (m)
  ivec4 steps;          // x steps, y light_steps, z octaves, w jitter (0 off: midpoints)
  vec4 octave;          // x a, y b, z c, w powder (0 off, 1 on)
  vec4 lobes;           // x g_forward, y g_back, z back_weight
  ivec4 block;          // x update_block, yz this frame's pixel inside each block (Bayer order), w unused
  ivec4 frame;          // xy the full-resolution frame (pixels) the blocks tile
};
GPU_END

#endif  // VOLGRAPH_CLOUD_MARCH_PARAMS_H
