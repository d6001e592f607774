#version 450
#extension GL_GOOGLE_include_directive : require
// cloud_march: the cloud layer, one coverage and type everywhere.
#include "include/cloud_march_body.glsl"
