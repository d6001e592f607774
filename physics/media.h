// Participating media maths shared by every fog technique and the CPU reference: Beer–
// Lambert transmittance, the numerically stable (1 − e^(−x))/x, the two front-to-back
// integration steps, exponential height fog in closed form, depth fog factors, and the
// artist inputs that convert to σ. CPU twin of shaders/include/media.glsl: change both
// together. Templates on the real type (float: what the GPU computes; double: the
// reference). Units: σ in 1/m, distances in m.
#pragma once

#include <algorithm>
#include <cmath>

namespace volgraph::physics {

// Below |x| = this, (1 − e^(−x))/x is summed as a series: the direct form cancels
// (float32 gives 1.0014 at x = 1e-5, 1.19 at 1e-7, 0 at 1e-9 and NaN at 0).
template <typename Real>
constexpr Real kSeriesBelow = Real(0.01);
// Exponents are clamped here so that e^(−x) cannot overflow float32 (e^88.7 does).
template <typename Real>
constexpr Real kMaxExponent = Real(80);

// (1 − e^(−x)) / x for any x (→ 1 as x → 0; grows like e^(−x)/|x| for x < 0, clamped
// at x = −kMaxExponent). Series: 1 − x/2 + x²/6 − x³/24 + x⁴/120 (error < x⁵/720).
template <typename Real>
Real one_minus_exp_over_x(Real x) {
  x = std::max(x, -kMaxExponent<Real>);
  if (std::abs(x) < kSeriesBelow<Real>) {
    return Real(1) + x * (Real(-1) / Real(2) + x * (Real(1) / Real(6) + x * (Real(-1) / Real(24) + x / Real(120))));
  }
  return (Real(1) - std::exp(-x)) / x;
}

// Beer–Lambert: e^(−σt·d), for σt ≥ 0 and d ≥ 0.
template <typename Real>
Real transmittance(Real sigma_t, Real distance) {
  return std::exp(-std::min(sigma_t * distance, Real(1e30)));
}

// ∫₀^length e^(−σt·s) ds = (1 − e^(−σt·length))/σt, stable as σt → 0 (→ length): the
// radiance per unit source of a source constant along the ray (a directional light in
// homogeneous fog); with the unit-density optical depth of height fog as `length`, that
// of a source proportional to the density.
template <typename Real>
Real attenuated_length(Real sigma_t, Real length) {
  return length * one_minus_exp_over_x(sigma_t * length);
}

// One channel of a front-to-back integration: radiance gathered so far and the
// transmittance from the eye to the current depth.
template <typename Real>
struct ScatterAccumulator {
  Real radiance = 0;
  Real transmittance = 1;
};

// Wronski 2014 (RTR4 eq. 14.15): the slice's in-scattered radiance per metre S,
// taken as constant, times its length dz, attenuated by the transmittance in front of
// it; then the slice's own extinction. Overestimates light in dense slices.
template <typename Real>
void integrate_wronski(ScatterAccumulator<Real>& a, Real in_scatter, Real sigma_t, Real dz) {
  a.radiance += a.transmittance * in_scatter * dz;
  a.transmittance *= transmittance(sigma_t, dz);
}

// Hillaire 2015 (RTR4 eq. 14.16), energy-conserving: S integrated against the
// slice's own extinction, ∫₀^dz S e^(−σt t) dt = S·dz·(1 − e^(−σt dz))/(σt dz); exact
// for constant S and σt, and stable as σt → 0 (it becomes S·dz).
template <typename Real>
void integrate_hillaire(ScatterAccumulator<Real>& a, Real in_scatter, Real sigma_t, Real dz) {
  a.radiance += a.transmittance * in_scatter * dz * one_minus_exp_over_x(sigma_t * dz);
  a.transmittance *= transmittance(sigma_t, dz);
}

// Optical depth through exponential height fog, σ(y) = σ_base·e^(−falloff·(y − base)),
// along origin + t·direction for t ∈ [0, length] (|direction| = 1), in closed form:
// σ_base·e^(−falloff(y₀ − base))·length·(1 − e^(−x))/x with x = falloff·direction_y·length.
template <typename Real>
Real height_fog_optical_depth(Real sigma_base, Real falloff, Real base_height, Real origin_y, Real direction_y, Real length) {
  const Real at_origin = std::exp(std::min(-falloff * (origin_y - base_height), kMaxExponent<Real>));
  return sigma_base * at_origin * length * one_minus_exp_over_x(falloff * direction_y * length);
}

// An optical depth standing for "no light gets through" (a directional light below the
// horizon seen through height fog): finite so that differences of two stay defined.
template <typename Real>
constexpr Real kInfiniteOpticalDepth = Real(1e30);

// The same optical depth for unit base density from origin_y toward a directional light
// along `direction_y`, to infinity: σ_base·e^(−falloff(y₀ − base))/(falloff·direction_y),
// the segment's closed form over the length where e^(−falloff·direction_y·length) has
// fallen by e^(−kMaxExponent); kInfiniteOpticalDepth for a level or downward direction
// (ever denser fog), and never above it.
template <typename Real>
Real height_fog_unit_depth_to_infinity(Real falloff, Real base_height, Real origin_y, Real direction_y) {
  if (!(direction_y > 0)) return kInfiniteOpticalDepth<Real>;
  const Real length = kMaxExponent<Real> / (falloff * direction_y);
  return std::min(height_fog_optical_depth(Real(1), falloff, base_height, origin_y, direction_y, length),
                  kInfiniteOpticalDepth<Real>);
}

// ∫₀^length e^(−(a + x·s/length)) ds = length·e^(−a)·(1 − e^(−x))/x: a source constant per
// unit length seen through an optical depth that grows linearly along the way, from a at
// the start by x across it — height fog under a directional light dimmed by the fog above
// each point, with length the unit-density optical depth along the view ray (the sun's
// optical depth is linear in it, and a + x is the view's plus the sun's at the far end).
// attenuated_length(σt, length) is a = 0, x = σt·length. Stable as x → 0 (series) and for
// large a (no e^(+x) formed).
template <typename Real>
Real attenuated_length_from(Real depth_at_start, Real depth_across, Real length) {
  const Real a = std::min(depth_at_start, kMaxExponent<Real>);
  if (std::abs(depth_across) < kSeriesBelow<Real>) return length * std::exp(-a) * one_minus_exp_over_x(depth_across);
  const Real end = std::clamp(depth_at_start + depth_across, -kMaxExponent<Real>, kMaxExponent<Real>);
  return length * (std::exp(-a) - std::exp(-end)) / depth_across;
}

// Depth fog (RTR4 eq. 14.12–14.14): the fraction f of the surface's radiance
// that remains at view distance z; the pixel is f·L_surface + (1 − f)·L_fog.
template <typename Real>
Real depth_fog_linear(Real z, Real z_start, Real z_end) {
  if (z_end <= z_start) return z < z_start ? Real(1) : Real(0);
  return std::clamp((z_end - z) / (z_end - z_start), Real(0), Real(1));
}
template <typename Real>
Real depth_fog_exponential(Real z, Real density) {
  return std::exp(-std::min(density * z, kMaxExponent<Real>));
}
template <typename Real>
Real depth_fog_exponential_squared(Real z, Real density) {
  const Real dz = std::min(density * z, Real(9));  // e^(−81) is 0 in float32 already
  return std::exp(-dz * dz);
}

// The smallest transmittance colour accepted when deriving σ from one: a colour of 0
// (log 0 = −∞) means "as opaque as this".
template <typename Real>
constexpr Real kMinTransmittance = Real(1e-6);
// Marches stop once every channel's transmittance is below this (media.glsl).
template <typename Real>
constexpr Real kNegligibleTransmittance = Real(1e-4);

// σt from the transmittance `colour` seen through `distance` metres (RTR4
// eq. 14.23): σt = −ln(colour)/distance.
template <typename Real>
Real sigma_t_from_transmittance(Real colour, Real distance) {
  return -std::log(std::clamp(colour, kMinTransmittance<Real>, Real(1))) / std::max(distance, Real(1e-6));
}

}  // namespace volgraph::physics
