#version 450
#extension GL_GOOGLE_include_directive : require
// raymarch_fog without a shadow map: every light reaches every sample (volumetric
// shadows aside). The march: shaders/include/raymarch_fog_body.glsl.
float light_visibility(int light, vec3 p) { return 1.0; }
bool media_shadow_mapped(int light) { return false; }
#include "include/raymarch_fog_body.glsl"
