#version 450
#extension GL_GOOGLE_include_directive : require
// fog_apply, second draw: the in-scattered radiance in front of the surface (added).
#include "include/fog_image_lookup.glsl"

layout(set = 0, binding = 3) uniform Frame { vec4 size; } frame;  // xy: the colour's size in pixels
layout(location = 0) out vec4 radiance;

void main() { radiance = vec4(fog_images(gl_FragCoord.xy, frame.size.xy).scattering, 0.0); }
