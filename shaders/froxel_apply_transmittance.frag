#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_apply, first draw: the surface's radiance times the transmittance to it
// (blended as destination × source).
#include "include/froxel_lookup.glsl"

layout(location = 0) out vec4 factor;

void main() { factor = vec4(fog_at_pixel(gl_FragCoord.xy - 0.5).transmittance, 1.0); }
