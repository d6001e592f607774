// Single scattering of one light along a camera ray through a homogeneous medium,
// unshadowed, from the camera to a distance: the I(t) that the light_volume pass
// evaluates at each face of its shadow volume (Billeter, Sintorn, Assarsson 2010, §3: the
// in-scattering of a lit segment [t0, t1] is I(t1) − I(t0)). CPU twin of
// shaders/include/light_volume_integral.glsl: change both together. Templates on the real
// type (float: what the GPU computes; double: tests).
//
// Per unit σs, along origin + s·direction (unit), s ∈ [0, length]:
//   I = ∫₀^length p_HG(g, cos θ(s)) · E(s) · T_light(s) · e^(−σt·s) ds
// the integrand of raymarch_fog's march in a homogeneous medium (lighting.glsl
// light_arriving, light_transmittance.glsl):
// - directional: E constant, T_light = 1 (the global fog does not dim a directional
//   light: its E is what arrives), so I = p_HG(θ)·E·(1 − e^(−σt·length))/σt;
// - point and spot: E = cone(s)·I_light/d(s)², T_light = e^(−σt·d(s)); by the airlight's
//   substitution s − t_c = h·sinh w (airlight.h: Sun et al. 2005, dt/d² = dw/d), composite
//   8-point Gauss–Legendre in w. A spot's smoothstep falloff has a kink (a jump of its
//   second derivative) where the ray crosses the outer and the inner cone: the interval
//   is cut at those crossings (roots of a quadratic) and each piece where the cone is
//   not zero gets kLightVolumePanels panels, so every panel integrates a smooth function.
// Measured (tests/unit/light_volume_integral_test.cpp, against a 2·10⁶-step midpoint sum
// in double): see the test; the GPU against this twin in tests/gpu/physics_twins_test.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "physics/airlight.h"
#include "physics/lighting.h"
#include "physics/media.h"
#include "physics/phase.h"

namespace volgraph::physics {

constexpr int kLightVolumePanels = 4;  // Gauss–Legendre panels per piece between cone crossings
constexpr int kLightTypeDirectional = 0, kLightTypePoint = 1, kLightTypeSpot = 2;  // lighting.glsl

// A light as lighting.glsl's Light holds it, per unit power.
template <typename Real>
struct RayLight {
  int type = kLightTypeDirectional;
  std::array<Real, 3> position{};
  std::array<Real, 3> direction{0, -1, 0};  // unit, the way its light travels
  Real cos_outer = -1, cos_inner = -1;      // spot
};

template <typename Real>
Real dot3(const std::array<Real, 3>& a, const std::array<Real, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// lighting.glsl spot_cone: the smooth falloff between the cones for light leaving along
// `travel` (unit); 1 for other lights.
template <typename Real>
Real spot_cone(const RayLight<Real>& light, const std::array<Real, 3>& travel) {
  if (light.type != kLightTypeSpot) return Real(1);
  return Real(smoothstep(double(light.cos_outer), double(light.cos_inner), double(dot3(travel, light.direction))));
}

// Up to 6 ray parameters, sorted: 0, the cone crossings inside (0, length), length.
template <typename Real>
struct RayCuts {
  std::array<Real, 6> at{};
  int count = 0;
  void add(Real s) {
    int i = count++;
    for (; i > 0 && at[size_t(i - 1)] > s; --i) at[size_t(i)] = at[size_t(i - 1)];
    at[size_t(i)] = s;
  }
};

// Where origin + s·direction crosses the cone of cosine c around the spot's axis (its
// forward nappe): (a0 + a1·s)² = c²·|v(s)|², v(s) = from_light + s·direction.
template <typename Real>
void add_cone_crossings(const std::array<Real, 3>& from_light, const std::array<Real, 3>& direction,
                        const std::array<Real, 3>& axis, Real c, Real length, RayCuts<Real>& cuts) {
  const Real a0 = dot3(from_light, axis), a1 = dot3(direction, axis);
  const Real q0 = dot3(from_light, from_light), q1 = dot3(from_light, direction);
  const Real qa = a1 * a1 - c * c, qb = Real(2) * (a0 * a1 - c * c * q1), qc = a0 * a0 - c * c * q0;
  std::array<Real, 2> roots{-1, -1};
  if (std::abs(qa) < Real(1e-12)) {
    if (qb != Real(0)) roots[0] = -qc / qb;
  } else {
    const Real discriminant = qb * qb - Real(4) * qa * qc;
    if (discriminant < Real(0)) return;
    const Real q = Real(-0.5) * (qb + std::copysign(std::sqrt(discriminant), qb));  // Numerical Recipes §5.6
    roots = {q / qa, q != Real(0) ? qc / q : Real(-1)};
  }
  for (const Real s : roots) {
    if (s > Real(0) && s < length && a0 + a1 * s > Real(0)) cuts.add(s);
  }
}

// ∫_a^b p_HG(g, cos θ) · cone · e^(−σt·(s + d)) / d² ds for a point or spot light, in
// w (s − t_c = h·sinh w, ds/d² = dw/d): `panels` panels of 8 Gauss–Legendre nodes.
template <typename Real>
Real point_scattering_piece(const RayLight<Real>& light, const AirlightGeometry<Real>& geometry,
                            const std::array<Real, 3>& direction, const std::array<Real, 3>& perpendicular, Real a, Real b,
                            Real sigma_t, Real g, int panels) {
  const Real h = geometry.h, t_c = geometry.t_c;
  const Real w0 = airlight_asinh((a - t_c) / h), w1 = airlight_asinh((b - t_c) / h);
  return gauss_legendre_panels(w0, w1, panels, [&](Real w) {
    const Real along = h * std::sinh(w), distance = h * std::cosh(w);
    const Real s = std::max(t_c + along, Real(0));
    std::array<Real, 3> travel{};
    for (size_t i = 0; i < 3; ++i) travel[i] = (along * direction[i] - perpendicular[i]) / distance;
    const Real attenuation = std::exp(-std::min(sigma_t * (s + distance), Real(80)));
    return phase_hg(g, -along / distance) * spot_cone(light, travel) * attenuation / distance;
  });
}

// I above for a point or spot light: the ray cut where it crosses the cones (and where the
// integrand becomes negligible, airlight_negligible_beyond), the pieces the cone lights
// integrated.
template <typename Real>
Real point_scattering_to(const RayLight<Real>& light, const std::array<Real, 3>& origin, const std::array<Real, 3>& direction,
                         Real length, Real sigma_t, Real g, int panels) {
  const AirlightGeometry<Real> geometry = airlight_geometry(origin, direction, light.position);
  const Real end = std::min(length, airlight_negligible_beyond(geometry, sigma_t));
  if (!(end > Real(0))) return Real(0);
  std::array<Real, 3> from_light{}, perpendicular{};
  for (size_t i = 0; i < 3; ++i) {
    from_light[i] = origin[i] - light.position[i];
    perpendicular[i] = -from_light[i] - geometry.t_c * direction[i];
  }
  RayCuts<Real> cuts;
  cuts.add(Real(0));
  cuts.add(end);
  if (light.type == kLightTypeSpot) {
    add_cone_crossings(from_light, direction, light.direction, light.cos_outer, end, cuts);
    add_cone_crossings(from_light, direction, light.direction, light.cos_inner, end, cuts);
  }
  Real sum = 0;
  for (int i = 0; i + 1 < cuts.count; ++i) {
    const Real a = cuts.at[size_t(i)], b = cuts.at[size_t(i + 1)];
    if (!(b > a)) continue;
    std::array<Real, 3> middle{};
    for (size_t k = 0; k < 3; ++k) middle[k] = from_light[k] + Real(0.5) * (a + b) * direction[k];
    const Real middle_distance = std::sqrt(dot3(middle, middle));
    for (Real& m : middle) m /= std::max(middle_distance, Real(1e-30));
    if (spot_cone(light, middle) <= Real(0)) continue;  // outside the outer cone: no light
    sum += point_scattering_piece(light, geometry, direction, perpendicular, a, b, sigma_t, g, panels);
  }
  return sum;
}

// I(length) per unit σs and unit light power (irradiance or intensity).
template <typename Real>
Real light_scattering_to(const RayLight<Real>& light, const std::array<Real, 3>& origin, const std::array<Real, 3>& direction,
                         Real length, Real sigma_t, Real g, int panels = kLightVolumePanels) {
  if (light.type == kLightTypeDirectional) {
    return phase_hg(g, -dot3(light.direction, direction)) * attenuated_length(sigma_t, length);
  }
  return point_scattering_to(light, origin, direction, length, sigma_t, g, panels);
}

}  // namespace volgraph::physics
