#version 450
#extension GL_GOOGLE_include_directive : require
// froxel_apply, second draw: the in-scattered radiance in front of the surface (added).
#include "include/froxel_lookup.glsl"

layout(location = 0) out vec4 radiance;

void main() { radiance = vec4(fog_at_pixel(gl_FragCoord.xy - 0.5).in_scatter, 0.0); }
