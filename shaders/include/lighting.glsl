// Light reaching a surface, DESIGN.md units. CPU twin: physics/lighting.h.
#ifndef VOLGRAPH_LIGHTING_GLSL
#define VOLGRAPH_LIGHTING_GLSL

const float PI = 3.14159265358979;
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;

#include "light.h"  // struct Light

// A spot light's smooth falloff between its outer and inner cones for light leaving it
// along `travel` (unit); 1 for other lights.
float spot_cone(Light light, vec3 travel) {
  if (int(light.position_type.w) != LIGHT_SPOT) return 1.0;
  return smoothstep(light.direction_cos_outer.w, light.power_cos_inner.w, dot(travel, light.direction_cos_outer.xyz));
}

// What one light delivers at `p`, unshadowed: the irradiance E on a surface facing it
// (directional: E; point and spot: I/d², spot with a smooth falloff between the inner
// and outer cones), and `travel` the unit direction its light travels at p.
vec3 light_arriving(Light light, vec3 p, out vec3 travel) {
  const int type = int(light.position_type.w);
  if (type == LIGHT_DIRECTIONAL) {
    travel = light.direction_cos_outer.xyz;
    return light.power_cos_inner.rgb;
  }
  const vec3 from_light = p - light.position_type.xyz;
  const float d2 = max(dot(from_light, from_light), 1e-12);
  travel = from_light * inversesqrt(d2);
  return light.power_cos_inner.rgb * (spot_cone(light, travel) / d2);
}

// Irradiance on a surface at `p` with normal `n` from one light, unshadowed: E·cos θ.
vec3 irradiance(Light light, vec3 p, vec3 n) {
  vec3 travel;
  const vec3 e = light_arriving(light, p, travel);
  return e * max(dot(n, -travel), 0.0);
}

// A Lambertian surface of albedo ρ under irradiance E reflects ρ/π · E.
vec3 lambert(vec3 albedo, vec3 irradiance_sum) { return albedo / PI * irradiance_sum; }

#endif
