#version 450
#extension GL_GOOGLE_include_directive : require
// atmosphere_aerial_perspective: the air's in-scattering and transmittance per froxel of the frame.
#include "include/atmosphere_aerial_perspective_body.glsl"
