#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency's back-face step: the solid objects' back faces in front of the opaque
// surface, their depth and their distance from the camera (float32: the solids' paths end
// there). The surface body runs for its sets (the same layouts as the surfaces' draws) and
// its discard.
#include "include/translucency_shadow_set.glsl"
#include "include/translucency.glsl"

layout(location = 0) out vec4 distance_out;  // r32f: the kept surface's distance (m), the solids' path ends
#include "include/surface_point.glsl"

void write_layer(SurfaceLayer layer, SurfacePoint point) { distance_out = vec4(point.distance, 0.0, 0.0, 0.0); }

#include "include/translucent_surface.glsl"
