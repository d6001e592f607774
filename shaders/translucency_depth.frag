#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency's back-face step: the solid objects' back faces in front of the opaque
// surface, depth only. The surface body runs for its sets (the same layouts as the
// surfaces' draws) and its discard; it writes no colour.
#include "include/shadow_set.glsl"
#include "include/translucency.glsl"

#include "include/surface_point.glsl"

void write_layer(SurfaceLayer layer, SurfacePoint point) {}

#include "include/translucent_surface.glsl"
