#version 450
#extension GL_GOOGLE_include_directive : require
// Shadow map: object space to the light's clip space (passes/shadow_map.cpp), with the
// texture coordinate for shadow_mask.frag's alpha test.
#include "include/object_uniforms.glsl"
#include "include/shadow_view.glsl"

layout(set = 0, binding = 0) uniform ShadowBlock { ShadowView view; } shadow;
layout(location = 0) in vec3 position;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec2 texture_uv;

void main() {
  texture_uv = uv;
  gl_Position = shadow.view.light_view_projection * (object.model * vec4(position, 1.0));
}
