#version 450
#extension GL_GOOGLE_include_directive : require
// Translucent shadow map: object space to the light's clip space (passes/translucent_shadow_map.cpp),
// with the world position and normal (Fresnel at the light's angle) and the texture coordinate.
#include "include/object_uniforms.glsl"
#include "include/shadow_view.glsl"

layout(set = 0, binding = 0) uniform ShadowBlock { ShadowView view; } shadow;
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;
layout(location = 2) out vec2 texture_uv;

void main() {
  const vec4 world = object.model * vec4(position, 1.0);
  world_position = world.xyz;
  world_normal = mat3(object.normal_matrix) * normal;
  texture_uv = uv;
  gl_Position = shadow.view.light_view_projection * world;
}
