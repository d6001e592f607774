// Per-object block, set 1 of every pass that rasterises the scene (passes/plumbing/scene_geometry.cpp).
#ifndef VOLGRAPH_OBJECT_UNIFORMS_GLSL
#define VOLGRAPH_OBJECT_UNIFORMS_GLSL

// graph/scene/scene.h's AlphaMode and VolumeKind, as the block codes them.
const int kAlphaOpaque = 0, kAlphaMask = 1, kAlphaBlend = 2;
const int kVolumeThinWalled = 0, kVolumeShell = 1, kVolumeSolid = 2;

layout(set = 1, binding = 0) uniform Object {
  mat4 model;
  mat4 normal_matrix;  // inverse transpose of the model's 3×3, in a mat4
  vec4 albedo;
  vec4 emissive;       // radiance
  vec4 translucency;   // coverage α, transmission, IOR, thickness (m)
  vec4 attenuation;    // σt per channel (1/m), volume kind
  vec4 alpha_test;     // alpha mode, cutoff
} object;

#endif
