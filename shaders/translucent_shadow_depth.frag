#version 450
#extension GL_GOOGLE_include_directive : require
// Translucent shadow map, depth: the same fragments as translucent_shadow.frag keep the nearest
// caster's depth (depth test less); the colour they blend is 1, which changes nothing.
#include "include/translucent_caster.glsl"

layout(location = 0) out vec4 transmittance;

void main() {
  vec3 t;
  if (!translucent_caster(t)) discard;
  transmittance = vec4(1.0);
}
