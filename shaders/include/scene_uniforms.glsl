// The scene pass's uniform blocks (passes/scene.cpp writes them, std140).
#ifndef VOLGRAPH_SCENE_UNIFORMS_GLSL
#define VOLGRAPH_SCENE_UNIFORMS_GLSL
#include "light_list.glsl"
#include "media_field.glsl"

layout(set = 0, binding = 0) uniform Frame {
  mat4 view_projection;
  vec4 ambient_irradiance;  // rgb, W/m²
  LightList light_list;
  MediaField media;  // the global and height fog (no volumes): they dim the light toward each surface
} frame;

#include "object_uniforms.glsl"

#endif
