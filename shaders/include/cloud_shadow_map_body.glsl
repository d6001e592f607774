// cloud_shadow_map (passes/clouds/cloud_shadow_map.cpp; wrapped by cloud_shadow_map.comp, and
// by cloud_shadow_map_weather.comp with CLOUD_WEATHER_MAP: the weather map bound): per texel, the optical depth
// τ = ∫ σt(ρ(q + s·to_sun)) ds through the cloud layer from the texel's point q on the
// layer's bottom plane toward the sun, `steps` midpoint samples from q to where the ray
// leaves the layer's top sphere, the density cloud_march's (cloud_layer.glsl). Sun at or
// below the horizon: a large τ (the ground is in the planet's shadow). τ in r.
// With `layers` N > 0 (params.steps.y) also the transmittance map (Schneider & Vos 2015):
// slice k of optical_depth_layers holds τ from the point at altitude bottom + (k + ½)/N ·
// (top − bottom) on the same ray from the texel's q, to the layer's top, by `steps`
// midpoint samples (cloud_march's transmittance_map variant reads it).
#include "include/cloud_shadow_map_params.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform CloudShadowMapParamsBlock { CloudShadowMapParams params; };
layout(set = 0, binding = 1) uniform texture3D shape;
layout(set = 0, binding = 2) uniform texture3D detail;
layout(set = 0, binding = 3) uniform texture2D curl;
layout(set = 0, binding = 4) uniform sampler noise;  // linear, repeat: the textures tile
layout(set = 0, binding = 5, rgba16f) uniform writeonly image2D optical_depth;
layout(set = 0, binding = 7, rgba16f) uniform writeonly image3D optical_depth_layers;  // size × size × max(layers, 1)
#ifdef CLOUD_WEATHER_MAP
layout(set = 0, binding = 6) uniform texture2D weather;  // cloud_weather_map.weather: r coverage, g type, a type weight
#endif

#include "include/cloud_layer.glsl"

const float HALF_MAX = 65504.0;    // rgba16f's largest value
const float BELOW_HORIZON = 1e4;   // τ where the sun is at or below the horizon: exp(−τ) is 0

// The texel's point on the bottom plane (cloud_shadow_view.h's texel ↔ point rule).
vec3 plane_point(ivec2 texel, ivec2 size) {
  const vec2 f = (vec2(texel) + 0.5) / vec2(size) - 0.5;
  return vec3(params.plane.x + f.x * params.plane.w, params.plane.y, params.plane.z + f.y * params.plane.w);
}

// τ toward the sun from q to where the ray leaves the layer's top sphere, `steps` midpoint samples.
float optical_depth_to_sun(vec3 q) {
  const vec3 to_sun = params.to_sun.xyz;
  float t0, t1;
  if (!sphere_roots(q, to_sun, altitude(q), params.layer.y, t0, t1) || t1 <= 0.0) return 0.0;
  const int n = max(params.steps.x, 1);
  const float ds = t1 / float(n);
  float tau = 0.0;
  for (int j = 0; j < n; ++j) tau += cloud_extinction(params.cloud.z, density(q + (float(j) + 0.5) * ds * to_sun)) * ds;
  return tau;
}

// τ from q's point: 0 without a sun or cloud, large below the horizon, finite (NaN → large).
float texel_optical_depth(vec3 q) {
  if (params.to_sun.w < 0.0 || params.cloud.x <= 0.0) return 0.0;
  if (params.to_sun.y <= 0.0) return BELOW_HORIZON;
  const float tau = optical_depth_to_sun(q);
  return (tau >= 0.0 && tau <= HALF_MAX) ? tau : (tau > HALF_MAX ? HALF_MAX : BELOW_HORIZON);
}

// The point of slice k of n on the sun's ray from q: where it reaches the slice's altitude
// (q itself where q already lies above it: the plane's edge is higher than its centre).
vec3 slice_point(vec3 q, int k, int n) {
  const float a = params.layer.x + (float(k) + 0.5) / float(n) * (params.layer.y - params.layer.x);
  float t0, t1;
  const bool meets = sphere_roots(q, params.to_sun.xyz, altitude(q), a, t0, t1);
  return q + (meets ? max(t1, 0.0) : 0.0) * params.to_sun.xyz;
}

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy), size = imageSize(optical_depth);
  if (any(greaterThanEqual(texel, size))) return;
  const vec3 q = plane_point(texel, size);
  imageStore(optical_depth, texel, vec4(texel_optical_depth(q), 0.0, 0.0, 1.0));
  const int n = params.steps.y;
  for (int k = 0; k < n; ++k) imageStore(optical_depth_layers, ivec3(texel, k), vec4(texel_optical_depth(slice_point(q, k, n)), 0.0, 0.0, 1.0));
}
