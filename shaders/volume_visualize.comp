#version 450
#extension GL_GOOGLE_include_directive : require
// volume_visualize: ray marching, isosurface and the slices' copy, with the 1D transfer function.
#include "include/volume_visualize_body.glsl"
