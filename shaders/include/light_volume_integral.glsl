// Single scattering of one light along a camera ray through a homogeneous medium,
// unshadowed, from the camera to a distance: the I(t) of Billeter, Sintorn, Assarsson 2010
// (§3) that light_volume evaluates at each face of its shadow volume. CPU twin:
// physics/light_volume_integral.h — change both together; the derivation, the
// quadrature and its measured error are documented there.
#ifndef VOLGRAPH_LIGHT_VOLUME_INTEGRAL_GLSL
#define VOLGRAPH_LIGHT_VOLUME_INTEGRAL_GLSL
#include "airlight.glsl"
#include "lighting.glsl"
#include "media.glsl"

const int LIGHT_VOLUME_PANELS = 4;  // Gauss–Legendre panels per piece between cone crossings

// Up to 6 ray parameters, sorted: 0, the cone crossings inside (0, length), length.
struct RayCuts {
  float at[6];
  int count;
};

void add_cut(inout RayCuts cuts, float s) {
  int i = cuts.count++;
  for (; i > 0 && cuts.at[i - 1] > s; --i) cuts.at[i] = cuts.at[i - 1];
  cuts.at[i] = s;
}

// Where origin + s·direction crosses the cone of cosine c around the spot's axis (its
// forward nappe): (a0 + a1·s)² = c²·|v(s)|², v(s) = from_light + s·direction.
void add_cone_crossings(vec3 from_light, vec3 direction, vec3 axis, float c, float len, inout RayCuts cuts) {
  const float a0 = dot(from_light, axis), a1 = dot(direction, axis);
  const float q0 = dot(from_light, from_light), q1 = dot(from_light, direction);
  const float qa = a1 * a1 - c * c, qb = 2.0 * (a0 * a1 - c * c * q1), qc = a0 * a0 - c * c * q0;
  vec2 roots = vec2(-1.0);
  if (abs(qa) < 1e-12) {
    if (qb != 0.0) roots.x = -qc / qb;
  } else {
    const float discriminant = qb * qb - 4.0 * qa * qc;
    if (discriminant < 0.0) return;
    const float q = -0.5 * (qb + (qb < 0.0 ? -1.0 : 1.0) * sqrt(discriminant));  // Numerical Recipes §5.6
    roots = vec2(q / qa, q != 0.0 ? qc / q : -1.0);
  }
  for (int i = 0; i < 2; ++i) {
    const float s = roots[i];
    if (s > 0.0 && s < len && a0 + a1 * s > 0.0) add_cut(cuts, s);
  }
}

// ∫_a^b p_HG(g, cos θ) · cone · e^(−σt·(s + d)) / d² ds for a point or spot light, in w
// (s − t_c = h·sinh w, ds/d² = dw/d): LIGHT_VOLUME_PANELS panels of 8 Gauss–Legendre nodes.
vec3 point_scattering_piece(Light light, AirlightGeometry geometry, vec3 direction, vec3 perpendicular, float a, float b,
                            vec3 sigma_t, float g) {
  const float h = geometry.h, t_c = geometry.t_c;
  const float w0 = airlight_asinh((a - t_c) / h), w1 = airlight_asinh((b - t_c) / h);
  const float panel = (w1 - w0) / float(LIGHT_VOLUME_PANELS);
  vec3 sum = vec3(0.0);
  for (int k = 0; k < LIGHT_VOLUME_PANELS; ++k) {
    const float centre = w0 + (float(k) + 0.5) * panel;
    for (int n = 0; n < 8; ++n) {
      const float x = (n < 4 ? -1.0 : 1.0) * GAUSS_LEGENDRE_8_NODES[n % 4];
      const float w = centre + 0.5 * panel * x;
      const float along = h * sinh(w), distance = h * cosh(w);
      const float s = max(t_c + along, 0.0);
      const vec3 travel = (along * direction - perpendicular) / distance;
      const vec3 attenuation = exp(-min(sigma_t * (s + distance), vec3(80.0)));
      sum += GAUSS_LEGENDRE_8_WEIGHTS[n % 4] * phase_hg(g, -along / distance) * spot_cone(light, travel) * attenuation / distance;
    }
  }
  return sum * 0.5 * panel;
}

// I for a point or spot light: the ray cut where it crosses the cones (and where the
// integrand becomes negligible), the pieces the cone lights integrated.
vec3 point_scattering_to(Light light, vec3 origin, vec3 direction, float len, vec3 sigma_t, float g) {
  const vec3 position = light.position_type.xyz;
  const AirlightGeometry geometry = airlight_geometry(origin, direction, position);
  const float least_sigma_t = min(sigma_t.r, min(sigma_t.g, sigma_t.b));
  const float end = min(len, airlight_negligible_beyond(geometry, least_sigma_t));
  if (!(end > 0.0)) return vec3(0.0);
  const vec3 from_light = origin - position;
  const vec3 perpendicular = -from_light - geometry.t_c * direction;
  RayCuts cuts;
  cuts.count = 0;
  add_cut(cuts, 0.0);
  add_cut(cuts, end);
  if (int(light.position_type.w) == LIGHT_SPOT) {
    add_cone_crossings(from_light, direction, light.direction_cos_outer.xyz, light.direction_cos_outer.w, end, cuts);
    add_cone_crossings(from_light, direction, light.direction_cos_outer.xyz, light.power_cos_inner.w, end, cuts);
  }
  vec3 sum = vec3(0.0);
  for (int i = 0; i + 1 < cuts.count; ++i) {
    const float a = cuts.at[i], b = cuts.at[i + 1];
    if (!(b > a)) continue;
    const vec3 middle = from_light + 0.5 * (a + b) * direction;
    if (spot_cone(light, middle / max(length(middle), 1e-30)) <= 0.0) continue;  // outside the outer cone: no light
    sum += point_scattering_piece(light, geometry, direction, perpendicular, a, b, sigma_t, g);
  }
  return sum;
}

// Per unit σs and unit light power: ∫₀^len p_HG·E·T_light·e^(−σt·s) ds along
// origin + s·direction (unit), unshadowed.
vec3 light_scattering_to(Light light, vec3 origin, vec3 direction, float len, vec3 sigma_t, float g) {
  if (int(light.position_type.w) == LIGHT_DIRECTIONAL) {
    return phase_hg(g, -dot(light.direction_cos_outer.xyz, direction)) * attenuated_length(sigma_t, len);
  }
  return point_scattering_to(light, origin, direction, len, sigma_t, g);
}

#endif
