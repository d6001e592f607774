// Single scattering of a point light along a ray through a homogeneous medium, without
// shadows — the "airlight" of Sun, Ramamoorthi, Narasimhan, Nayar 2005, "A Practical
// Analytic Single Scattering Model for Real Time Rendering" (§3). CPU twin of
// shaders/include/airlight.glsl: change both together. Templates on the real type (float:
// what the GPU computes; double: tests and the reference).
//
// The ray is origin + t·direction, t ∈ [0, length]; the light sits at distance h from the
// ray's line, its projection on it at t_c. A point at t is d(t) = √(h² + (t − t_c)²) from the
// light; light travels to it through d and then t back to the camera, so per unit σs·I:
//   A = ∫₀^length p(θ(t)) · e^(−σt·(t + d(t))) / d(t)² dt,   cos θ = −(t − t_c)/d(t).
// With t − t_c = h·tan γ (Sun et al.'s substitution) dt/d² = dγ/h; without extinction and
// with isotropic phase A = (γ1 − γ0)/(4π h), γ0 = −atan(t_c/h), γ1 = atan((length − t_c)/h),
// in closed form. With extinction Sun et al. tabulate F(u, v) = ∫₀^v e^(−u·tan ξ) dξ
// (ξ = π/4 + γ/2); here A is evaluated instead by a fixed composite Gauss–Legendre rule
// (kAirlightPanels panels of 8 nodes) in w, t − t_c = h·sinh w, which also takes the
// Henyey–Greenstein phase; in γ the exponential's scale squeezes into the last panel far
// from the light, in w it stays a few units wide. Measured (tests/unit/airlight_test.cpp,
// against a 10⁶-step midpoint sum in t; t_c ∈ [−3, 30] m, h ∈ [0.05, 3] m, length ∈ [1, 100] m,
// σt ∈ [0, 10] /m, g ∈ [−0.5, 0.9]): relative error ≤ 1e-6 in double, ≤ 3e-5 in float.
//
// h is clamped to kAirlightMinDistance: a ray through the light (h → 0) diverges like 1/h.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "physics/phase.h"

namespace volgraph::physics {

// The smallest distance between the ray and the light used (m).
template <typename Real>
constexpr Real kAirlightMinDistance = Real(1e-4);
constexpr int kAirlightPanels = 8;

// 8-point Gauss–Legendre nodes (positive half) and weights on [−1, 1] (Abramowitz & Stegun
// Table 25.4).
template <typename Real>
constexpr std::array<Real, 4> kGaussLegendre8Nodes = {Real(0.1834346424956498), Real(0.5255324099163290),
                                                      Real(0.7966664774136267), Real(0.9602898564975363)};
template <typename Real>
constexpr std::array<Real, 4> kGaussLegendre8Weights = {Real(0.3626837833783620), Real(0.3137066458778873),
                                                        Real(0.2223810344533745), Real(0.1012285362903763)};

// ∫ f(w) dw over [w0, w1] by `panels` equal panels of 8 Gauss–Legendre nodes each.
template <typename Real, typename Integrand>
Real gauss_legendre_panels(Real w0, Real w1, int panels, const Integrand& f) {
  const Real panel = (w1 - w0) / Real(panels);
  Real sum = 0;
  for (int k = 0; k < panels; ++k) {
    const Real centre = w0 + (Real(k) + Real(0.5)) * panel;
    for (size_t n = 0; n < 8; ++n) {
      const Real x = (n < 4 ? -1 : 1) * kGaussLegendre8Nodes<Real>[n % 4];
      sum += kGaussLegendre8Weights<Real>[n % 4] * f(centre + Real(0.5) * panel * x);
    }
  }
  return sum * Real(0.5) * panel;
}

// Where a light stands relative to a ray (unit direction): its projection t_c along the
// ray and its distance h from the ray's line, clamped to kAirlightMinDistance.
template <typename Real>
struct AirlightGeometry {
  Real t_c = 0;
  Real h = 0;
};

template <typename Real>
AirlightGeometry<Real> airlight_geometry(const std::array<Real, 3>& origin, const std::array<Real, 3>& direction,
                                         const std::array<Real, 3>& light) {
  std::array<Real, 3> to_light{};
  for (size_t i = 0; i < 3; ++i) to_light[i] = light[i] - origin[i];
  const Real t_c = to_light[0] * direction[0] + to_light[1] * direction[1] + to_light[2] * direction[2];
  Real h2 = 0;
  for (size_t i = 0; i < 3; ++i) {
    const Real off = to_light[i] - t_c * direction[i];
    h2 += off * off;
  }
  return {t_c, std::max(std::sqrt(h2), kAirlightMinDistance<Real>)};
}

// ∫₀^length dt / (4π d(t)²): the isotropic airlight without extinction (Sun et al. 2005,
// σt → 0): (atan((length − t_c)/h) + atan(t_c/h)) / (4π h). The sum of the two atans is the
// angle the segment subtends at the light, evaluated as one atan2(h·length, h² + t_c(t_c −
// length)) — the two terms cancel in float when the light is far behind or ahead.
template <typename Real>
Real airlight_no_extinction(const AirlightGeometry<Real>& g, Real length) {
  return std::atan2(g.h * length, g.h * g.h + g.t_c * (g.t_c - length)) * kInvFourPi<Real> / g.h;
}

// Light travels t + d(t) to reach the camera via the point at t, a length that grows with
// t from d(0): beyond the t where it exceeds d(0) by kAirlightCutoff/σt the integrand is
// below e^(−kAirlightCutoff) of its value at the camera and is left out. Solving
// t + √(h² + (t − t_c)²) = K, K = d(0) + c/σt, gives t = (K² − d(0)²) / (2(K − t_c)), with
// K² − d(0)² written (c/σt)(2d(0) + c/σt) so it does not cancel.
template <typename Real>
constexpr Real kAirlightCutoff = Real(40);

template <typename Real>
Real airlight_negligible_beyond(const AirlightGeometry<Real>& g, Real sigma_t) {
  if (!(sigma_t > Real(0))) return std::numeric_limits<Real>::infinity();
  const Real margin = kAirlightCutoff<Real> / sigma_t;
  const Real at_camera = std::sqrt(g.h * g.h + g.t_c * g.t_c);
  return margin * (Real(2) * at_camera + margin) / (Real(2) * (at_camera - g.t_c + margin));
}

// asinh as log(|x| + √(x² + 1)) with the sign restored: exact in the tails, where some
// GPU asinh cancel (x ≪ 0); |x| is capped at 1e15 so x² stays finite in float.
template <typename Real>
Real airlight_asinh(Real x) {
  const Real a = std::min(std::abs(x), Real(1e15));
  return std::copysign(std::log(a + std::sqrt(a * a + Real(1))), x);
}

// The airlight integral A above with extinction σt and HG phase g (g = 0: isotropic),
// in w with t − t_c = h·sinh w (dt/d² = dw/d, cos θ = −tanh w): the 1/d² peak near the
// light and the exponential's scale 1/(σt·d) far from it are both a few units of w wide.
template <typename Real>
Real airlight(const AirlightGeometry<Real>& geometry, Real length, Real sigma_t, Real g) {
  const Real h = geometry.h, t_c = geometry.t_c;
  const Real end = std::min(length, airlight_negligible_beyond(geometry, sigma_t));
  const Real w0 = airlight_asinh(-t_c / h), w1 = airlight_asinh((end - t_c) / h);
  return gauss_legendre_panels(w0, w1, kAirlightPanels, [&](Real w) {
    const Real along = h * std::sinh(w), distance = h * std::cosh(w);
    const Real t = std::max(t_c + along, Real(0));
    const Real attenuation = std::exp(-std::min(sigma_t * (t + distance), Real(80)));
    return phase_hg(g, -along / distance) * attenuation / distance;
  });
}

}  // namespace volgraph::physics
