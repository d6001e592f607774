#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency, a surface's first draw: what lies behind times the layer's transmittance
// (blended as destination × source).
#include "include/translucency_shadow_set.glsl"
#include "include/translucency.glsl"

layout(location = 0) out vec4 factor;
#include "include/surface_point.glsl"

void write_layer(SurfaceLayer layer, SurfacePoint point) { factor = vec4(layer.transmittance, 1.0); }

#include "include/translucent_surface.glsl"
