#version 450
#extension GL_GOOGLE_include_directive : require
// aerial_perspective_apply, second draw: the light the air scatters toward the camera in front of the surface (added).
#include "include/aerial_apply.glsl"

layout(location = 0) out vec4 radiance;

void main() { radiance = vec4(aerial_at_pixel(gl_FragCoord.xy - 0.5).in_scatter, 0.0); }
