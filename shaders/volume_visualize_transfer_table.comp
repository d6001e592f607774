#version 450
#extension GL_GOOGLE_include_directive : require
// volume_visualize, variant raymarch with the 2D transfer table (VOLUME_TRANSFER_TABLE).
#define VOLUME_TRANSFER_TABLE
#include "include/volume_visualize_body.glsl"
