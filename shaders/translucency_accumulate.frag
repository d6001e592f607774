#version 450
#extension GL_GOOGLE_include_directive : require
// Weighted blended order-independent transparency (McGuire & Bavoil 2013), every surface
// in one draw in any order, both targets added: Σ w·radiance and Σ w·opacity (target 0),
// and the optical depth −ln T per channel (target 1), whose sum gives the transmittances'
// product exactly in any order (McGuire 2015's coloured transmission; a sum, so both
// targets blend alike). Opacity is 1 − the mean transmittance; w is oit_weight's.
#include "include/translucency_shadow_set.glsl"
#include "include/translucency.glsl"

layout(location = 0) out vec4 accumulation;
layout(location = 1) out vec4 optical_depth;
#include "include/surface_point.glsl"

void write_layer(SurfaceLayer layer, SurfacePoint point) {
  const float opacity = 1.0 - (layer.transmittance.r + layer.transmittance.g + layer.transmittance.b) / 3.0;
  const float peak = max(layer.radiance.r, max(layer.radiance.g, layer.radiance.b));
  const float w = oit_weight(point.view_depth, opacity, peak);
  accumulation = vec4(layer.radiance * w, opacity * w);
  optical_depth = vec4(transmittance_depth(layer.transmittance), 1.0);
}

#include "include/translucent_surface.glsl"
