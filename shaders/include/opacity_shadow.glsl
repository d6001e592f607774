// Opacity shadow maps (Kim & Neumann 2001), kept as optical depth: for every texel of a
// shadow map's light view, the local volumes' optical depth from the light to evenly
// spaced layers along that texel's light ray (its column, from the view's near plane to
// its far plane). Written by opacity_shadow_map (shaders/opacity_shadow_map.comp); any
// pass that lights a point by that light reads e^(−τ) with one trilinear lookup, and
// multiplies in the global and height fog's transmittance in closed form
// (light_transmittance.glsl), which the map leaves out.
#ifndef VOLGRAPH_OPACITY_SHADOW_GLSL
#define VOLGRAPH_OPACITY_SHADOW_GLSL
#include "media.glsl"
#include "shadow_view.glsl"

struct LightColumn {
  vec3 start;  // on the view's near plane (toward the light)
  vec3 end;    // on its far plane
};

// The light ray through shadow-map NDC `ndc` (+y up).
LightColumn light_column(ShadowView view, vec2 ndc) {
  const vec4 near_point = view.clip_to_world * vec4(ndc, 0.0, 1.0);
  const vec4 far_point = view.clip_to_world * vec4(ndc, 1.0, 1.0);
  return LightColumn(near_point.xyz / near_point.w, far_point.xyz / far_point.w);
}

// Layer k of n holds τ at the fraction (k + 0.5)/n of its column: texture coordinate w
// is the fraction itself.
float light_column_fraction(LightColumn column, vec3 p) {
  const vec3 along = column.end - column.start;
  return dot(p - column.start, along) / dot(along, along);
}

// e^(−τ) from the map at p; 1 where p is outside the light's view or no light is shadowed.
vec3 opacity_map_transmittance(texture3D optical_depth, sampler linear_clamp, ShadowView view, vec3 p) {
  if (view.params.w < 0.0) return vec3(1.0);
  const vec4 clip = view.light_view_projection * vec4(p, 1.0);
  if (clip.w <= 0.0) return vec3(1.0);
  const vec2 ndc = clip.xy / clip.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return vec3(1.0);
  const float w = light_column_fraction(light_column(view, ndc), p);
  const vec3 uvw = vec3(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5, w);  // row 0 at the top
  const vec3 tau = textureLod(sampler3D(optical_depth, linear_clamp), uvw, 0.0).rgb;
  return exp(-min(tau, vec3(MAX_EXPONENT)));
}

#endif
