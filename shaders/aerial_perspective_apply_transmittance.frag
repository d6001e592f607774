#version 450
#extension GL_GOOGLE_include_directive : require
// aerial_perspective_apply, first draw: the air's transmittance in front of the surface (multiplied).
#include "include/aerial_apply.glsl"

layout(location = 0) out vec4 transmittance;

void main() { transmittance = vec4(aerial_at_pixel(gl_FragCoord.xy - 0.5).transmittance, 1.0); }
