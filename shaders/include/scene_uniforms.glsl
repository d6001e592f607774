// The scene pass's uniform blocks (passes/scene.cpp writes them, std140).
#ifndef VOLGRAPH_SCENE_UNIFORMS_GLSL
#define VOLGRAPH_SCENE_UNIFORMS_GLSL
#include "lighting.glsl"

const int MAX_LIGHTS = 16;

layout(set = 0, binding = 0) uniform Frame {
  mat4 view_projection;
  vec4 ambient_irradiance;  // rgb, W/m²
  ivec4 counts;             // x: lights
  Light lights[MAX_LIGHTS];
} frame;

layout(set = 1, binding = 0) uniform Object {
  mat4 model;
  mat4 normal_matrix;  // inverse transpose of the model's 3×3, in a mat4
  vec4 albedo;
  vec4 emissive;       // radiance
} object;

#endif
