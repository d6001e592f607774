#version 450
#extension GL_GOOGLE_include_directive : require
// fog_apply (depth_aware), second draw: the in-scattered radiance in front of the surface (added).
#include "include/fog_image_lookup_depth_aware.glsl"

layout(location = 0) out vec4 radiance;

void main() { radiance = vec4(fog_at_pixel(gl_FragCoord.xy).in_scatter, 0.0); }
