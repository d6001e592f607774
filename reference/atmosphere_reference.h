// The CPU reference of a planet's atmosphere (graph/scene/scene.h Atmosphere, Bruneton
// 2017's model) in double precision, with the physics of physics/atmosphere.h: the sky's
// radiance along a ray, the sun's disk, the ground, and aerial perspective.
//
// Frame: the planet's, its centre at the origin, +Y up above the scene's origin (the
// scene's axes; a scene point p is p + (0, bottom_radius + origin_altitude, 0) here).
//
// Scattering is split by order (the number of scattering events, a ground reflection
// counting as one, as in Bruneton 2017's iterated orders):
// - order 1 (single scattering, and the sun's light reflected once by the ground) is
//   deterministic: adaptive Simpson quadrature along the ray (Lyness 1969) held below
//   `relative_tolerance` of the integral, the view ray's transmittance from physics'
//   optical_depth at every node, the sun's from physics' sun_transmittance;
// - orders 2…N by Monte Carlo path tracing with next-event estimation toward the sun,
//   tallied per order, a fixed seed per (ray key, sample, channel), so a pixel's value is
//   the same on every run and with any number of threads. A path is drawn by the
//   densities of one channel (the hero, chosen at random) and tallies every channel by
//   one-sample multiple importance sampling over the three (Wilkie et al. 2014's hero
//   wavelengths, Veach 1997's balance heuristic): 2-3× less variance per second than a
//   walk per channel. Every vertex is a forced collision: its distance drawn from the
//   segment's tabulated optical depth (128 trapezoids) mixed with a uniform density and
//   weighted by the exact transmittance (physics' optical_depth); where a segment ends on
//   the Lambertian ground (ground_albedo) the ground is the vertex instead with
//   probability 1 − T̃ (clamped to [0.1, 0.9]); from the camera both the air and the
//   ground (by its exact transmittance) are taken. Paths end by Russian roulette from
//   order 3 on. Checked against delta tracking (Woodcock 1965) on one ray (earth, sun and
//   view 60° up, 131072 paths): order 2 agrees within 0.8 standard errors (0.3 %).
// Why Monte Carlo for the higher orders: it shares no discretisation with the LUT
// techniques it measures (Hillaire 2020's isotropic multiple-scattering approximation,
// Bruneton 2017's 4D tables of iterated orders), its only approximation is the sample
// count, and its error is stated: the standard error of each order's estimate.
// The order count N is the first order ≥ 2 after which the orders traced (paths run
// until Russian roulette ends them, at most `max_orders` vertices) add at most
// `order_threshold` of orders 1…N (largest channel): a criterion on the whole tail, as a
// single high order's estimate is too noisy to stop on. What orders N+1… add is the
// stated residual; orders past max_orders are not traced.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "graph/scene/scene.h"
#include "reference/image_render.h"

namespace volgraph::reference {

struct AtmosphereSun {
  Vec3 direction{0, 1, 0};   // unit, toward the sun (planet frame)
  Vec3 irradiance{1, 1, 1};  // E at the top of the atmosphere, W/m² per channel, on a surface facing it
  double angular_radius = 0.004675;  // rad
};

// The atmosphere's sun: the scene's directional light `sun_light` (E, the opposite of its
// direction of travel) and the atmosphere's angular radius; nullopt without one.
std::optional<AtmosphereSun> scene_sun(const Atmosphere& atmosphere, const std::vector<Light>& lights);

struct AtmosphereReferenceSettings {
  // Single scattering: each panel's Richardson error estimate |S₂ − S₁|/15 (largest
  // channel) is held below relative_tolerance × (the ray's integral) × (panel length /
  // ray length), from `initial_panels` equal panels bisected at most `max_depth` times.
  double relative_tolerance = 1e-6;
  uint32_t initial_panels = 64;
  uint32_t max_depth = 30;
  // Orders ≥ 2: paths per ray (0: single scattering only, exact to the quadrature's
  // tolerance), their length cap, the convergence threshold. Measured on a 32x18 sky of
  // the earth preset from 2 m, 90° field of view, CPU time on one thread of an AMD EPYC:
  // single scattering alone 1.7 s; 64 paths a ray add 2.6-2.9 s (a walk per channel
  // took 3× the paths' time for the same noise). The Monte Carlo's standard error of a pixel's total is
  // on average 3.5 % (at most 6.6 %) of it at noon (sun 60° up) and 9.4 % (at most 30 %)
  // at sunset (sun 2° up) with 64 paths, 1.8 % (3.1 %) and 4.8 % (12 %) with 256.
  uint32_t samples = 64;
  uint32_t max_orders = 64;
  double order_threshold = 1e-3;
  uint64_t seed = 1;
};

// Radiance by scattering order along one ray: radiance[k] is order k + 1.
struct ScatteringOrders {
  std::vector<Vec3> radiance;
  std::vector<Vec3> standard_error;  // of each order's estimate (0 for the deterministic order 1)
  uint32_t orders = 0;               // N: orders 1…N make `total`
  Vec3 total{0, 0, 0};               // Σ orders 1…N
  Vec3 residual{0, 0, 0};            // Σ orders N+1…max_orders (as traced)
  // The paths' own estimate of order 1 (next-event estimation at their first vertex) and
  // its standard error: a check of the sampling against the quadrature, not used.
  Vec3 order_one_estimate{0, 0, 0}, order_one_error{0, 0, 0};
};

struct SkySample {
  Vec3 radiance{0, 0, 0};       // scattering (orders 1…N, ground included) + the sun's disk
  Vec3 sun_disk{0, 0, 0};       // the sun's radiance times the transmittance, inside its disk
  Vec3 transmittance{1, 1, 1};  // from the camera to the end of the ray (the ground or space)
  bool hits_ground = false;
  ScatteringOrders scattering;
};

struct AerialPerspectiveSample {
  Vec3 in_scattered{0, 0, 0};   // orders 1…N scattered toward the camera on [0, d]
  Vec3 transmittance{1, 1, 1};  // from the camera to distance d
  ScatteringOrders scattering;
};

class AtmosphereReference {
 public:
  AtmosphereReference(const Atmosphere& atmosphere, const AtmosphereSun& sun,
                      const AtmosphereReferenceSettings& settings = {});

  // e^(−τ) from (r, mu) to the ray's end (the ground or the top).
  Vec3 transmittance(double r, double mu) const;
  // Single scattering (Rayleigh + Mie) toward the viewer at (r, mu) from its ray to the
  // boundary, the sun at zenith cosine mu_s and at cosine nu from the view direction
  // (Bruneton 2017's parameters; the sun's irradiance is this reference's).
  Vec3 single_scattering(double r, double mu, double mu_s, double nu) const;
  // The same from `position` along unit `direction` over [0, length] (inside the atmosphere).
  Vec3 single_scattering(const Vec3& position, const Vec3& direction, double length) const;

  // The radiance of a camera ray from `position` (anywhere: above the top it enters the
  // atmosphere first; below the ground it starts on the ground straight above) along unit
  // `direction`: every order, the ground, the sun's disk.
  // `key` seeds the ray's paths (a pixel index).
  SkySample sky(const Vec3& position, const Vec3& direction, uint64_t key) const;
  // Aerial perspective of a segment from `position` to distance `distance` along unit
  // `direction`: the light scattered toward the camera on it and its transmittance.
  AerialPerspectiveSample aerial_perspective(const Vec3& position, const Vec3& direction, double distance,
                                             uint64_t key) const;

  // The sun's light scattered once toward the viewer per metre at `point` (planet frame)
  // for a ray of unit `direction`: (σ_R P_R(ν) + σ_M P_M(ν)) E T_sun(point), what order 1
  // integrates (the view's transmittance not included).
  Vec3 air_in_scattering(const Vec3& point, const Vec3& direction) const;
  // The air's transmittance over the first `distance` m from `position` along unit
  // `direction`, from where aerial_perspective starts (the ground straight above a point
  // below it; the entry into the atmosphere from above it).
  Vec3 transmittance_along(const Vec3& position, const Vec3& direction, double distance) const;

  const Atmosphere& atmosphere() const { return atmosphere_; }
  const AtmosphereSun& sun() const { return sun_; }
  const AtmosphereReferenceSettings& settings() const { return settings_; }

 private:
  Vec3 single_scattering_along(const Vec3& position, const Vec3& direction, double length, const Vec3& sun) const;
  Vec3 in_scattering(const Vec3& point, const Vec3& direction, const Vec3& sun) const;
  Vec3 ground_direct(const Vec3& ground_point) const;
  ScatteringOrders scatter(const Vec3& position, const Vec3& direction, double length, bool ends_on_ground,
                           uint64_t key) const;

  Atmosphere atmosphere_;
  AtmosphereSun sun_;
  AtmosphereReferenceSettings settings_;
};

// A scene point in the planet's frame: p + (0, bottom_radius + origin_altitude, 0).
Vec3 planet_position(const Atmosphere& atmosphere, const Vec3& scene_point);

struct SkyImage {
  ReferenceImage image;
  uint32_t max_orders = 0;            // the largest N over the pixels
  double max_relative_residual = 0;   // the largest residual / total (largest channel) over the pixels
  // The Monte Carlo's standard error of each pixel's total (orders 2…N, independent),
  // over its total, largest channel: the mean and the largest over the pixels.
  double mean_relative_standard_error = 0, max_relative_standard_error = 0;
};

// The sky seen by `camera` (scene frame, DESIGN.md's pixel convention, one ray through
// each pixel's centre: settings.samples_per_axis is ignored), threaded as render_image;
// pixel (i, j) seeds its paths with the key j·width + i.
SkyImage render_sky_image(const AtmosphereReference& reference, const Camera& camera, const RenderSettings& settings);

}  // namespace volgraph::reference
