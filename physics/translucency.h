// Translucent and refracting surfaces (Real-Time Rendering 4th ed., §14.5): Fresnel
// reflectance, the refraction vector, and the colour absorbed through a thickness. CPU
// twin of shaders/include/translucency.glsl: change both together. Templates on the real
// type so tests can check float (what the GPU computes) and the reference can use double.
// Conventions: `to_incident` is the unit vector from the surface point back toward where
// the light (or the view ray) comes from, `normal` the unit normal on its side
// (dot(to_incident, normal) ≥ 0); `eta` the relative index n₁/n₂ (incident side over
// transmitted side).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace volgraph::physics {

template <typename Real>
using Vec3Of = std::array<Real, 3>;

// Reflectance at normal incidence between media of indices n1 and n2: ((n1 − n2)/(n1 + n2))²
// (RTR4 eq. 9.17; 0.04 for air and glass, n = 1.5).
template <typename Real>
Real fresnel_f0(Real n1, Real n2) {
  const Real r = (n1 - n2) / (n1 + n2);
  return r * r;
}

// Schlick's approximation: F = F0 + (1 − F0)(1 − cos θ)⁵ (RTR4 eq. 9.16), cos θ clamped to [0, 1].
template <typename Real>
Real fresnel_schlick(Real f0, Real cos_theta) {
  const Real m = Real(1) - std::clamp(cos_theta, Real(0), Real(1));
  const Real m2 = m * m;
  return f0 + (Real(1) - f0) * m2 * m2 * m;
}

// The refracted direction by Bec's form (RTR4 eq. 14.28–14.29): w = eta (l·n),
// k = √(1 + (w − eta)(w + eta)), t = (w − k) n − eta l; none beyond the critical angle
// (total internal reflection: 1 + (w − eta)(w + eta) < 0). With eta = 1, t = −l exactly
// (taken apart: the form itself would round).
template <typename Real>
std::optional<Vec3Of<Real>> refract_bec(const Vec3Of<Real>& to_incident, const Vec3Of<Real>& normal, Real eta) {
  // No interface: straight on, exactly (the form's w − k rounds to a few ulps, not to 0).
  if (eta == Real(1)) return Vec3Of<Real>{-to_incident[0], -to_incident[1], -to_incident[2]};
  const Real w = eta * (to_incident[0] * normal[0] + to_incident[1] * normal[1] + to_incident[2] * normal[2]);
  const Real radicand = Real(1) + (w - eta) * (w + eta);
  if (radicand < Real(0)) return std::nullopt;
  const Real k = std::sqrt(radicand);
  return Vec3Of<Real>{(w - k) * normal[0] - eta * to_incident[0], (w - k) * normal[1] - eta * to_incident[1],
                      (w - k) * normal[2] - eta * to_incident[2]};
}

// The extinction that leaves transmittance `color` (a channel) after `distance` m:
// σt = −ln(color)/distance (RTR4 eq. 14.23). A colour of 0 is held at 1e-30 (σt finite,
// e^(−σt·distance) = 1e-30): the slab is opaque, and no Inf reaches a pass.
template <typename Real>
Real sigma_t_from_color(Real color, Real distance) {
  return -std::log(std::clamp(color, Real(1e-30), Real(1))) / distance;
}

// Beer–Lambert through a slab `thickness` m thick along a ray at cosine `cos_transmitted`
// to its normal inside: e^(−σt·thickness / cos) — the longer path at an angle. A grazing
// ray (cos → 0) transmits nothing.
template <typename Real>
Real slab_transmittance(Real sigma_t, Real thickness, Real cos_transmitted) {
  const Real c = std::abs(cos_transmitted);
  if (c <= Real(0)) return thickness > Real(0) && sigma_t > Real(0) ? Real(0) : Real(1);
  return std::exp(-sigma_t * thickness / c);
}

}  // namespace volgraph::physics
