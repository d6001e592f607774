// A planet's atmosphere (graph/scene/scene.h Atmosphere; Bruneton 2017's model): densities,
// coefficients, ray–sphere distances, optical depth and transmittance. CPU twin of
// shaders/include/atmosphere.glsl — change both together. Used by the atmosphere passes'
// tests, the CPU reference and the loader.
//
// A point of the atmosphere is given as (r, mu): its distance r from the planet's centre
// (m) and the cosine mu of the angle between the ray's direction and the local zenith,
// as in Bruneton 2017. Altitudes are r − bottom_radius.
#pragma once

#include <optional>

#include "graph/scene/scene.h"

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

// Where a ray from (r, mu) meets a sphere of `radius` about the planet's centre: the
// smallest positive distance, or nullopt when it does not. Stable at planet scale: the
// quadratic's constant term comes from the altitude as c = h (2R + h) (h = r − radius),
// never as r² − R², and the root is taken in the form that does not cancel.
std::optional<double> distance_to_sphere(double r, double mu, double radius);

// Distance from (r, mu) to the top of the atmosphere along the ray (r ≤ top_radius), and
// to the ground when the ray hits it (nullopt otherwise).
double distance_to_top(const Atmosphere& atmosphere, double r, double mu);
std::optional<double> distance_to_ground(const Atmosphere& atmosphere, double r, double mu);
bool ray_hits_ground(const Atmosphere& atmosphere, double r, double mu);
// Where the ray ends: the ground when it hits it, else the top.
double distance_to_boundary(const Atmosphere& atmosphere, double r, double mu);

// The radius and zenith cosine at distance d along the ray from (r, mu) (the law of
// cosines; r_d ≥ 0).
double radius_at(double r, double mu, double d);
double mu_at(double r, double mu, double d);

// ∫ extinction along the ray from (r, mu) for `length` m (per channel), by Gauss–Legendre
// panels fine enough for the profiles' scale heights (relative error below 1e-7 for the
// earth preset).
Vec3 optical_depth(const Atmosphere& atmosphere, double r, double mu, double length);
// The same to the ray's boundary (the ground or the top).
Vec3 optical_depth_to_boundary(const Atmosphere& atmosphere, double r, double mu);
// Straight up from altitude h to the top, in closed form: each layer's exponential and
// linear terms integrated exactly (the clamp to [0, 1] handled piecewise).
Vec3 zenith_optical_depth(const Atmosphere& atmosphere, double altitude);
// e^(−optical_depth_to_boundary): what reaches (r, mu) from the end of its ray.
Vec3 transmittance_to_boundary(const Atmosphere& atmosphere, double r, double mu);
// The sun's transmittance at (r, mu_s), 0 where the ground hides the sun's centre;
// Bruneton 2017 smooths it over the sun's disk: the visible fraction of a disk of the
// sun's angular radius above the horizon, times the transmittance to the top.
Vec3 sun_transmittance(const Atmosphere& atmosphere, double r, double mu_s);

// The Mie phase function the atmosphere names (Henyey–Greenstein, or Cornette & Shanks
// 1992: 3/(8π) (1 − g²)(1 + cos²θ) / ((2 + g²)(1 + g² − 2g cosθ)^1.5)), cos_theta between
// the light's direction of travel and the scattered direction.
double mie_phase(const Atmosphere& atmosphere, double cos_theta);

// The preset `name` ("earth", "mars"), or nullopt for an unknown name.
std::optional<Atmosphere> atmosphere_preset(const std::string& name);

}  // namespace volgraph::physics
