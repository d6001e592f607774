// Phase functions, normalised over the sphere (∫ p dω = 1). CPU twin of
// shaders/include/phase.glsl: change both together. `cos_theta` is the cosine of the
// scattering angle, between the light's direction of travel and the scattered
// direction (toward the viewer): forward scattering is cos_theta = 1, g > 0.
// Templates on the real type so tests can check float (what the GPU computes) and the
// reference can use double.
#pragma once

#include <algorithm>
#include <cmath>

namespace volgraph::physics {

template <typename Real>
constexpr Real kInvFourPi = Real(0.25 / 3.14159265358979323846);

template <typename Real>
Real phase_isotropic() {
  return kInvFourPi<Real>;
}

// Rayleigh scattering (small particles): 3/(16π)·(1 + cos²θ).
template <typename Real>
Real phase_rayleigh(Real cos_theta) {
  return Real(3) / Real(4) * kInvFourPi<Real> * (Real(1) + cos_theta * cos_theta);
}

// 1 + g² − 2g cosθ, the HG denominator's base, as a sum of non-negative terms:
// (1 − g)² + 2g(1 − cosθ) for g ≥ 0 and (1 + g)² − 2g(1 + cosθ) for g < 0, so it keeps its
// precision as g → ±1 at any angle (the first form alone cancels to nothing at g → −1,
// cosθ = −1: 5 % off in float on an NVIDIA H200, where fused multiply-adds round it otherwise).
template <typename Real>
Real phase_hg_base(Real g, Real cos_theta) {
  if (g >= Real(0)) return (Real(1) - g) * (Real(1) - g) + Real(2) * g * (Real(1) - cos_theta);
  return (Real(1) + g) * (Real(1) + g) - Real(2) * g * (Real(1) + cos_theta);
}

// Henyey–Greenstein 1941: (1 − g²) / (4π (1 + g² − 2g cosθ)^1.5), mean cosine g. The
// denominator's base is phase_hg_base, and 1 − g² is written (1 − g)(1 + g): both keep
// their precision as g → ±1, where the textbook form cancels to nothing.
template <typename Real>
Real phase_hg(Real g, Real cos_theta) {
  const Real one_minus_g = Real(1) - g;
  const Real base = phase_hg_base(g, cos_theta);
  const Real denominator = std::max(base * std::sqrt(base), Real(1e-30));
  return kInvFourPi<Real> * one_minus_g * (Real(1) + g) / denominator;
}

// Inverse CDF of Henyey–Greenstein's cosine (Henyey & Greenstein 1941; e.g. Pharr, Jakob,
// Humphreys, PBRT 4th ed. §11.3.1): the cosine whose density is phase_hg(g, ·) · 2π for
// uniform xi in [0, 1); uniform for |g| < 1e-3.
inline double sample_hg_cosine(double g, double xi) {
  if (std::abs(g) < 1e-3) return 2 * xi - 1;
  const double s = (1 - g * g) / (1 - g + 2 * g * xi);
  return std::clamp((1 + g * g - s * s) / (2 * g), -1.0, 1.0);
}

// Cornette & Shanks 1992 ("Physically reasonable analytic expression for the
// single-scattering phase function", Applied Optics 31, eq. 4), as Bruneton 2017's
// MiePhaseFunction: 3/(8π) (1 − g²)(1 + cos²θ) / ((2 + g²)(1 + g² − 2g cosθ)^1.5); the
// denominator's base written as in phase_hg.
template <typename Real>
Real phase_cornette_shanks(Real g, Real cos_theta) {
  const Real one_minus_g = Real(1) - g;
  const Real base = phase_hg_base(g, cos_theta);
  const Real denominator = std::max((Real(2) + g * g) * base * std::sqrt(base), Real(1e-30));
  return Real(1.5) * kInvFourPi<Real> * one_minus_g * (Real(1) + g) * (Real(1) + cos_theta * cos_theta) / denominator;
}

// Above this |g| the forward peak of HG (1 + g)/(4π(1 − g)²) exceeds fp16's largest
// value (65504): passes that store phase-weighted values in rgba16f clamp g to it.
template <typename Real>
constexpr Real kHgMaxAbsGForFp16 = Real(0.998);

// Schlick's approximation of HG (Blasi, Le Saëc, Schlick 1993): k ≈ 1.55g − 0.55g³, which
// leaves (−1, 1) for |g| > 0.938; clamped to ±kSchlickMaxK so the phase stays finite.
template <typename Real>
constexpr Real kSchlickMaxK = Real(0.9999);

template <typename Real>
Real schlick_k(Real g) {
  const Real k = Real(1.55) * g - Real(0.55) * g * g * g;
  return std::clamp(k, -kSchlickMaxK<Real>, kSchlickMaxK<Real>);
}

// (1 − k²) / (4π (1 − k cosθ)²), the denominator as (1 − k) + k(1 − cosθ) for k ≥ 0
// (and (1 + k) − k(1 + cosθ) for k < 0) so it keeps its precision near the peak.
template <typename Real>
Real phase_schlick(Real k, Real cos_theta) {
  const Real base = k >= Real(0) ? (Real(1) - k) + k * (Real(1) - cos_theta) : (Real(1) + k) - k * (Real(1) + cos_theta);
  return kInvFourPi<Real> * (Real(1) - k) * (Real(1) + k) / std::max(base * base, Real(1e-30));
}

// Two HG lobes, a forward and a backward one, mixed — the two-term Henyey–Greenstein
// function (Kattawar 1975, "A three-parameter analytic phase function for multiple
// scattering calculations", JQSRT 15, 839–849):
// w·p_HG(g_forward) + (1 − w)·p_HG(g_backward).
template <typename Real>
Real phase_dual_hg(Real g_forward, Real g_backward, Real w_forward, Real cos_theta) {
  return w_forward * phase_hg(g_forward, cos_theta) + (Real(1) - w_forward) * phase_hg(g_backward, cos_theta);
}

}  // namespace volgraph::physics
