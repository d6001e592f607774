// Light reaching a surface, DESIGN.md units. CPU twin: passes/shading/lighting.h.
#ifndef VOLGRAPH_LIGHTING_GLSL
#define VOLGRAPH_LIGHTING_GLSL

const float PI = 3.14159265358979;
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;

struct Light {
  vec4 position_type;        // xyz position (point, spot), w type
  vec4 direction_cos_outer;  // xyz direction the light travels (directional, spot), w cos(outer cone)
  vec4 power_cos_inner;      // rgb irradiance (directional, W/m²) or intensity (point, spot, W/sr); w cos(inner cone)
};

// Irradiance on a surface at `p` with normal `n` from one light, unshadowed: E·cos θ.
// Point and spot: E = I/d²; spot: smooth falloff between the inner and outer cones.
vec3 irradiance(Light light, vec3 p, vec3 n) {
  const int type = int(light.position_type.w);
  if (type == LIGHT_DIRECTIONAL) {
    return light.power_cos_inner.rgb * max(dot(n, -light.direction_cos_outer.xyz), 0.0);
  }
  const vec3 to_light = light.position_type.xyz - p;
  const float d2 = max(dot(to_light, to_light), 1e-12);
  const vec3 l = to_light * inversesqrt(d2);
  float cone = 1.0;
  if (type == LIGHT_SPOT) {
    cone = smoothstep(light.direction_cos_outer.w, light.power_cos_inner.w, dot(-l, light.direction_cos_outer.xyz));
  }
  return light.power_cos_inner.rgb * (cone * max(dot(n, l), 0.0) / d2);
}

// A Lambertian surface of albedo ρ under irradiance E reflects ρ/π · E.
vec3 lambert(vec3 albedo, vec3 irradiance_sum) { return albedo / PI * irradiance_sum; }

#endif
