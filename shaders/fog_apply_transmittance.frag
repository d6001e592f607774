#version 450
#extension GL_GOOGLE_include_directive : require
// fog_apply, first draw: the surface's radiance times the transmittance to it
// (blended as destination × source).
#include "include/fog_image_lookup.glsl"

layout(set = 0, binding = 3) uniform Frame { vec4 size; } frame;  // xy: the colour's size in pixels
layout(location = 0) out vec4 factor;

void main() { factor = vec4(fog_images(gl_FragCoord.xy, frame.size.xy).transmittance, 1.0); }
