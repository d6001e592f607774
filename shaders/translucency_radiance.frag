#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency, a surface's second draw: the layer's radiance added (source + destination).
#include "include/translucency_shadow_set.glsl"
#include "include/translucency.glsl"

layout(location = 0) out vec4 radiance;
#include "include/surface_point.glsl"

void write_layer(SurfaceLayer layer, SurfacePoint point) { radiance = vec4(layer.radiance, 0.0); }  // alpha 0: the colour's alpha is kept

#include "include/translucent_surface.glsl"
