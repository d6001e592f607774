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

#include "object_uniforms.glsl"

#endif
