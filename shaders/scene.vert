#version 450
#extension GL_GOOGLE_include_directive : require
// Opaque scene: object space to world and clip space (passes/scene.cpp).
#include "include/scene_uniforms.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;
layout(location = 2) out vec2 texture_uv;
// The same depth in every pipeline that draws a surface (translucency's depth peeling
// tests its layers for equality).
invariant gl_Position;

void main() {
  const vec4 world = object.model * vec4(position, 1.0);
  world_position = world.xyz;
  world_normal = mat3(object.normal_matrix) * normal;
  texture_uv = uv;
  gl_Position = frame.view_projection * world;
}
