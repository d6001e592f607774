#version 450
#extension GL_GOOGLE_include_directive : require
// Translucency, a surface in one draw (dual-source blending): the layer's radiance plus
// what lies behind times its transmittance, blended as source0 + destination × source1.
#include "include/translucency_shadow_set.glsl"
#include "include/translucency.glsl"

layout(location = 0, index = 0) out vec4 radiance;
layout(location = 0, index = 1) out vec4 factor;
#include "include/surface_point.glsl"

// The alphas keep the colour's alpha: 0 + a × 1.
void write_layer(SurfaceLayer layer, SurfacePoint point) {
  radiance = vec4(layer.radiance, 0.0);
  factor = vec4(layer.transmittance, 1.0);
}

#include "include/translucent_surface.glsl"
