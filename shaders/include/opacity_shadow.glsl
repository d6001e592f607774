// Opacity shadow maps (Kim & Neumann 2001), kept as optical depth: for every texel of a
// shadow map's light view, the local volumes' optical depth from the light to evenly
// spaced layers along that texel's light ray (its column): from the view's near plane to
// its far plane, or from the column's first medium at a fixed spacing (deep opacity maps,
// Yuksel & Keyser 2008); the alpha channel records which (OpacityLayerPlacement). Written by opacity_shadow_map (shaders/opacity_shadow_map.comp); any
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

// The fraction of its column at which p lies (0 at the near plane, 1 at the far plane).
float light_column_fraction(LightColumn column, vec3 p) {
  const vec3 along = column.end - column.start;
  return dot(p - column.start, along) / dot(along, along);
}

// Where a column's n layers lie, recorded in the map's alpha channel: layer 0's alpha holds
// `start`, every other layer's `span`, both as fractions of the column; texture coordinate
// w = (fraction − start) / span, so layer k holds τ at start + (k + 0.5)·span/n.
// Regular map (Kim & Neumann 2001): start 0 (the near plane), span 1 — w is the fraction
// itself. Deep map (Yuksel & Keyser 2008, sec. 3): layer 0's centre on the column's first
// medium d0 and spacing Δ, start = d0 − Δ/2, span = n·Δ; clamping w below layer 0 gives
// τ at d0 in front of it (nothing occludes there), and beyond the last layer its τ.
struct OpacityLayerPlacement {
  float start;
  float span;
};

float opacity_layer_w(OpacityLayerPlacement placement, float fraction) {
  return (fraction - placement.start) / placement.span;
}

// e^(−τ) from the map at p; 1 where p is outside the light's view or no light is shadowed.
vec3 opacity_map_transmittance(texture3D optical_depth, sampler linear_clamp, ShadowView view, vec3 p) {
  if (view.params.w < 0.0) return vec3(1.0);
  const vec4 clip = view.light_view_projection * vec4(p, 1.0);
  if (clip.w <= 0.0) return vec3(1.0);
  const vec2 ndc = clip.xy / clip.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return vec3(1.0);
  const vec2 uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);  // row 0 at the top
  const float layers = float(textureSize(sampler3D(optical_depth, linear_clamp), 0).z);
  // The placement, blended between columns as τ is: layer 0's and layer 1's alpha.
  const float start = textureLod(sampler3D(optical_depth, linear_clamp), vec3(uv, 0.5 / layers), 0.0).a;
  const float span = layers > 1.0 ? textureLod(sampler3D(optical_depth, linear_clamp), vec3(uv, 1.5 / layers), 0.0).a : 1.0;
  const float w = opacity_layer_w(OpacityLayerPlacement(start, span), light_column_fraction(light_column(view, ndc), p));
  const vec3 tau = textureLod(sampler3D(optical_depth, linear_clamp), vec3(uv, w), 0.0).rgb;
  return exp(-min(tau, vec3(MAX_EXPONENT)));
}

#endif
