// The per-object block, set 1 of every pass that rasterises the scene (passes/plumbing/scene_geometry.cpp packs it), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_OBJECT_UNIFORMS_H
#define VOLGRAPH_OBJECT_UNIFORMS_H
#include "gpu_struct.h"

GPU_BEGIN
GPU_STRUCT(ObjectUniforms) {
  mat4 model;
  mat4 normal_matrix;  // inverse transpose of the model's 3×3, in a mat4
  vec4 albedo;
  vec4 emissive;       // rgb radiance; w the interface's roughness (blurs what a solid refracts)
  vec4 translucency;   // coverage α, transmission, IOR, thickness (m)
  vec4 attenuation;    // σt per channel (1/m), volume kind
  vec4 alpha_test;     // alpha mode, cutoff, the red and blue channels' IORs (dispersion)
};
GPU_END

#endif  // VOLGRAPH_OBJECT_UNIFORMS_H
