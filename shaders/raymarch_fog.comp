#version 450
#extension GL_GOOGLE_include_directive : require
// raymarch_fog with every light reaching every sample (volumetric shadows aside) (set 1:
// include/fog_light_visibility.glsl). The march: shaders/include/raymarch_fog_body.glsl.
#include "include/fog_light_visibility.glsl"
#include "include/raymarch_fog_body.glsl"
