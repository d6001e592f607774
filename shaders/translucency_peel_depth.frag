#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency's depth peeling, one layer's depth (Everitt 2001, peeled back to front):
// every translucent surface in front of the opaque one and in front of the layer peeled
// before (back_depth's binding holds it), depth only; the depth test keeps the farthest.
// The surface body runs for its sets and its discards; it writes no colour.
#define TRANSLUCENT_PEELING
#include "include/shadow_set.glsl"
#include "include/translucency.glsl"

#include "include/surface_point.glsl"

void write_layer(SurfaceLayer layer, SurfacePoint point) {}

#include "include/translucent_surface.glsl"
