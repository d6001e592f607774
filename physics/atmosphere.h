// A planet's atmosphere (graph/scene/scene.h Atmosphere; Bruneton 2017's model): densities,
// coefficients, ray–sphere distances, optical depth and transmittance. CPU twin of
// shaders/include/atmosphere.glsl — change both together. Used by the atmosphere passes'
// tests, the CPU reference and the loader.
//
// A point of the atmosphere is given as (r, mu): its distance r from the planet's centre
// (m) and the cosine mu of the angle between the ray's direction and the local zenith,
// as in Bruneton 2017. Altitudes are r − bottom_radius.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "graph/scene/scene.h"
#include "shaders/include/atmosphere_parameters.h"

namespace volgraph::physics {

// A layer's and a profile's density at altitude h (m), clamped to [0, 1].
double layer_density(const DensityLayer& layer, double altitude);
double profile_density(const DensityProfile& profile, double altitude);

// The coefficients (1/m, per channel) at altitude h.
Vec3 rayleigh_scattering_at(const Atmosphere& atmosphere, double altitude);
Vec3 mie_scattering_at(const Atmosphere& atmosphere, double altitude);
Vec3 mie_extinction_at(const Atmosphere& atmosphere, double altitude);
Vec3 absorption_at(const Atmosphere& atmosphere, double altitude);
Vec3 extinction_at(const Atmosphere& atmosphere, double altitude);  // Rayleigh + Mie extinction + absorption

// A ray from (r, mu) and a sphere of `radius` about the planet's centre: the points at
// distance d with d² + 2bd + c = 0, b = r·mu, c = r² − radius². Stable at planet scale: c
// comes from the altitude as c = h (2·radius + h) (h = r − radius), never as r² − radius²,
// and each root is taken in the form that does not cancel (Numerical Recipes §5.6: one root
// as −b ∓ √Δ with the sign of b, the other as c over it). Templates on the real type so
// tests check float, what the GPU computes (shaders/include/atmosphere.glsl).
template <typename Real>
Real sphere_constant_term(Real r, Real radius) {
  const Real h = r - radius;
  return h * (Real(2) * radius + h);
}

// The nearer root −b − √Δ (Δ = b² − c clamped at 0): the entry into the sphere from
// outside. Written c / (−b + √Δ) when b < 0, where −b − √Δ would cancel.
template <typename Real>
Real sphere_near_root(Real b, Real c) {
  const Real sqrt_discriminant = std::sqrt(std::max(b * b - c, Real(0)));
  if (b < Real(0)) return c / (sqrt_discriminant - b);
  return -b - sqrt_discriminant;
}

// The farther root −b + √Δ: the exit from the sphere. Written −c / (b + √Δ) when b > 0.
template <typename Real>
Real sphere_far_root(Real b, Real c) {
  const Real sqrt_discriminant = std::sqrt(std::max(b * b - c, Real(0)));
  if (b > Real(0)) return -c / std::max(b + sqrt_discriminant, std::numeric_limits<Real>::min());
  return sqrt_discriminant - b;
}

// Where a ray from (r, mu) meets a sphere of `radius` about the planet's centre: from
// inside (r < radius) where it leaves the sphere; from outside or on it, where it enters
// (0 on the sphere heading inward), nullopt when it misses or heads away.
template <typename Real>
std::optional<Real> distance_to_sphere(Real r, Real mu, Real radius) {
  const Real b = r * mu, c = sphere_constant_term(r, radius);
  if (c < Real(0)) return std::max(sphere_far_root(b, c), Real(0));
  if (b >= Real(0) || b * b - c < Real(0)) return std::nullopt;
  return std::max(sphere_near_root(b, c), Real(0));
}

// Distance from (r, mu) to the top of the atmosphere along the ray, the ground ignored
// (Bruneton 2017, DistanceToTopAtmosphereBoundary): where the ray leaves the top sphere;
// r ≤ top_radius (above it, see enter_atmosphere).
double distance_to_top(const Atmosphere& atmosphere, double r, double mu);
// To the ground when the ray hits it (Bruneton 2017, DistanceToBottomAtmosphereBoundary),
// nullopt otherwise.
std::optional<double> distance_to_ground(const Atmosphere& atmosphere, double r, double mu);
// Bruneton 2017, RayIntersectsGround: mu < 0 and r²(mu² − 1) + bottom² ≥ 0 (the
// discriminant as b² − c, c from the altitude).
bool ray_hits_ground(const Atmosphere& atmosphere, double r, double mu);
// Where the ray ends: the ground when it hits it, else the top.
double distance_to_boundary(const Atmosphere& atmosphere, double r, double mu);
// A camera above the atmosphere (r > top_radius): the distance along its ray to the top
// sphere, where Hillaire 2020's code moves the ray's origin (0 when r ≤ top_radius),
// nullopt when the ray misses the atmosphere.
std::optional<double> enter_atmosphere(const Atmosphere& atmosphere, double r, double mu);

// The radius and zenith cosine at distance d along the ray from (r, mu) (the law of
// cosines, Bruneton 2017 ComputeSingleScatteringIntegrand's r_d and mu_d; r_d ≥ 0). r_d is
// written r + d(d + 2r·mu) / (r + r_d) so the altitude r_d − bottom keeps its precision.
double radius_at(double r, double mu, double d);
double mu_at(double r, double mu, double d);
// The sun's zenith cosine at distance d along the ray (r, mu) whose direction makes cosine
// nu with the sun's, the sun at zenith cosine mu_s at its start (Bruneton 2017:
// (r mu_s + d nu) / r_d).
double mu_s_at(double r, double mu, double mu_s, double nu, double d);
// The altitude there, r_d − bottom, as (r − bottom) + d(d + 2r·mu) / (r + r_d): in float
// (the GLSL twin) it keeps its relative precision where r_d − bottom would round to 0.5 m.
double altitude_at(const Atmosphere& atmosphere, double r, double mu, double d);

// ∫ extinction along the ray from (r, mu) for `length` m (per channel), by 8-point
// Gauss–Legendre panels between the profiles' kinks (layer boundaries, where a layer's
// density clamps at 0 or 1, the ray's lowest point), each panel spanning about two
// of the smallest scale heights in altitude (at most four: 8-point Gauss–Legendre's error on
// an exponential over k scale heights is ~2e-23·k^17 relative; below 1e-9 for the presets,
// tested). A layer's scale height counts only below the altitude where its exponential
// falls under e^(−80) (another break): thin air (H = 1 mm) costs a few dozen panels, not
// 4096. The presets are unchanged (their e^(−80) lies above the top). ~12 µs for a ray to
// the top of the earth's atmosphere, ~6 µs in 1 mm air (AMD EPYC, 2 cores shared, -O2).
Vec3 optical_depth(const Atmosphere& atmosphere, double r, double mu, double length);
// The GLSL twin's rule (atmosphere.glsl optical_depth, what fills the transmittance LUT):
// `panels` equal panels of 4-point Gauss–Legendre over [0, length].
Vec3 optical_depth_fixed(const Atmosphere& atmosphere, double r, double mu, double length, int panels);
// The same to the ray's boundary (the ground or the top).
Vec3 optical_depth_to_boundary(const Atmosphere& atmosphere, double r, double mu);
// Straight up from altitude h to the top, in closed form: each layer's exponential and
// linear terms integrated exactly (the clamp to [0, 1] handled piecewise).
Vec3 zenith_optical_depth(const Atmosphere& atmosphere, double altitude);
// ∫ profile density dh from altitude `from` to `to` (from ≤ to), in closed form.
double profile_integral(const DensityProfile& profile, double from, double to);
// e^(−optical_depth_to_boundary): what reaches (r, mu) from the end of its ray.
Vec3 transmittance_to_boundary(const Atmosphere& atmosphere, double r, double mu);
// e^(−optical depth to the top), the ground ignored: what Bruneton 2017's transmittance
// texture holds (GetTransmittanceToTopAtmosphereBoundary); below the horizon, the horizon's
// value (the texture's clamped lookup), never a ray through the planet.
Vec3 transmittance_to_top(const Atmosphere& atmosphere, double r, double mu);
// The fraction of the sun's disk above the horizon at (r, mu_s) (Bruneton 2017,
// GetTransmittanceToSun): smoothstep over ±sin θ_h·(angular radius) about the horizon's
// cosine cos θ_h = −√(1 − (bottom / r)²) — 1/2 when the sun's centre is on the horizon, 0
// once the whole disk is below.
double sun_visible_fraction(const Atmosphere& atmosphere, double r, double mu_s);
// The sun's transmittance at (r, mu_s): sun_visible_fraction × transmittance_to_top
// (Bruneton 2017, GetTransmittanceToSun).
Vec3 sun_transmittance(const Atmosphere& atmosphere, double r, double mu_s);

// The Mie phase function the atmosphere names (Henyey–Greenstein, or Cornette & Shanks
// 1992: 3/(8π) (1 − g²)(1 + cos²θ) / ((2 + g²)(1 + g² − 2g cosθ)^1.5)), cos_theta between
// the light's direction of travel and the scattered direction.
double mie_phase(const Atmosphere& atmosphere, double cos_theta);

// The zenith cosine of the horizon at r: −√(1 − (bottom / r)²), from the altitude.
double mu_horizon(const Atmosphere& atmosphere, double r);

// The preset `name` ("earth", "mars"), or nullopt for an unknown name.
std::optional<Atmosphere> atmosphere_preset(const std::string& name);

// The atmosphere's uniform block: written once for GLSL and C++ (shaders/include/atmosphere_parameters.h).
using GpuAtmosphere = gpu::AtmosphereParameters;
static_assert(sizeof(GpuAtmosphere) == 240);
constexpr float kMiePhaseHenyeyGreenstein = 0, kMiePhaseCornetteShanks = 1;
GpuAtmosphere pack_atmosphere(const Atmosphere& atmosphere);

}  // namespace volgraph::physics
