#version 450
#extension GL_GOOGLE_include_directive : require
// fog_apply (depth_aware), first draw: the surface's radiance times the transmittance to it
// (blended as destination × source).
#include "include/fog_image_lookup_depth_aware.glsl"

layout(location = 0) out vec4 factor;

void main() { factor = vec4(fog_at_pixel(gl_FragCoord.xy).transmittance, 1.0); }
