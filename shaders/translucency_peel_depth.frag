#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency's depth peeling, one layer's depth (Everitt 2001, peeled back to front):
// every translucent surface in front of the opaque one and in front of the layer peeled
// before (back_depth's binding holds it), its depth and its distance from the camera
// (float32); the depth test keeps the farthest. The surface body runs for its sets and its
// discards.
#define TRANSLUCENT_PEELING
#include "include/translucency_shadow_set.glsl"
#include "include/translucency.glsl"

layout(location = 0) out vec4 distance_out;  // r32f: the kept surface's distance (m), the solids' path ends
#include "include/surface_point.glsl"

void write_layer(SurfaceLayer layer, SurfacePoint point) { distance_out = vec4(point.distance, 0.0, 0.0, 0.0); }

#include "include/translucent_surface.glsl"
