// The scene's media as passes receive them (std140; C++ packs them in physics/media_field.cpp
// pack_media), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_MEDIA_FIELD_H
#define VOLGRAPH_MEDIA_FIELD_H
#include "gpu_struct.h"

// The most local volumes a scene may have (physics::kMaxMediumVolumes: passes refuse more).
#define GPU_MAX_MEDIUM_VOLUMES 8

GPU_BEGIN
GPU_STRUCT(MediumCoefficients) {
  vec4 sigma_s_g;  // rgb σs (1/m), w g
  vec4 sigma_a;    // rgb σa (1/m)
  vec4 emission;   // rgb radiance per metre
};

GPU_STRUCT(MediumVolume) {
  mat4 world_to_local;
  vec4 size_shape;  // xyz size (box edges, sphere radius in x, ellipsoid radii), w shape
  vec4 fade;        // x edge fade (m)
  vec4 noise;       // x octaves (0: none), y 1 / scale (per local unit), z coverage
  MediumCoefficients medium;
};

GPU_STRUCT(MediaField) {
  ivec4 counts;                    // x volumes, y global fog present, z height fog present
  MediumCoefficients fog;
  MediumCoefficients height_fog;   // at base height
  vec4 height;                     // x base height (m), y falloff (1/m)
  MediumVolume volumes[GPU_MAX_MEDIUM_VOLUMES];
};
GPU_END

#endif  // VOLGRAPH_MEDIA_FIELD_H
