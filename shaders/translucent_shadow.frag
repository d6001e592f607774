#version 450
#extension GL_GOOGLE_include_directive : require
// Translucent shadow map, colour: each translucent caster in front of the opaque map multiplies
// the texel by its transmittance (blended as destination × source; cleared to 1).
#include "include/translucent_caster.glsl"

layout(location = 0) out vec4 transmittance;

void main() {
  vec3 t;
  if (!translucent_caster(t)) discard;
  transmittance = vec4(t, 1.0);
}
