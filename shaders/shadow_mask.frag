#version 450
#extension GL_GOOGLE_include_directive : require
// Shadow map, fragment: a texel of an alpha-masked material (glTF alphaMode MASK) whose
// coverage is below its cutoff is a hole in the map as in the camera's view
// (scene_shading.glsl's test); every other fragment keeps its depth.
#include "include/material_textures.glsl"
#include "include/object_uniforms.glsl"

layout(location = 0) in vec2 texture_uv;

void main() {
  if (int(object.alpha_test.x) != kAlphaMask) return;
  if (material_coverage(object.translucency.x, texture_uv) < object.alpha_test.y) discard;
}
