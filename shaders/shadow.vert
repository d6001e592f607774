#version 450
#extension GL_GOOGLE_include_directive : require
// Shadow map: object space to the light's clip space (passes/shadow_map.cpp).
#include "include/object_uniforms.glsl"
#include "include/shadow_view.glsl"

layout(set = 0, binding = 0) uniform ShadowBlock { ShadowView view; } shadow;
layout(location = 0) in vec3 position;

void main() { gl_Position = shadow.view.light_view_projection * (object.model * vec4(position, 1.0)); }
