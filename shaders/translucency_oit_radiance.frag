#version 450
#extension GL_GOOGLE_include_directive : require
// Weighted blended OIT's resolve, second draw: + the layers' weighted mean radiance.
#include "include/oit_resolve.glsl"

layout(location = 0) out vec4 radiance;
void main() { radiance = vec4(mean_radiance_at(ivec2(gl_FragCoord.xy)), 0.0); }  // alpha 0: the colour's alpha is kept
