// The light the atmosphere scatters toward a viewer along a ray (Hillaire 2020 §5.3, the
// sky-view LUT's integral; §4 for the scattering): from (r, mu) to the ray's end at the top
// of the atmosphere or the ground, for a sun of unit illuminance at zenith cosine mu_s
// whose direction makes cosine nu with the ray's,
//   L = ∫ T(0, t) [σs_R(t) p_R(nu) + σs_M(t) p_M(nu)) T_sun(t) + σs(t) Ψ_ms(t)] dt
// sampled as Hillaire 2020 does — a sample count between min and max (more for longer
// rays), quadratically spaced ((s/n)² of the length), each at `sample_offset` of its step,
// the energy-conserving step (S − S·T)/σt — but at other defaults: Hillaire's 4–14 samples
// at 0.3 of each step are first order (the error falls as 1/n: 16 % at worst on the earth
// preset against the reference's quadrature, tests/reference/sky_sampling_test.cpp), the
// midpoint (0.5) second order; 40 midpoint samples are within 0.42 % on every ray. Ψ_ms is the multiple-scattering term
// (atmosphere_multiscattering.h), or none for single scattering alone. CPU twin of
// shaders/include/atmosphere_sky.glsl (which reads T_sun and Ψ_ms from their LUTs) —
// change both together.
#pragma once

#include <functional>

#include "graph/scene/scene.h"
#include "physics/atmosphere_lut.h"

namespace volgraph::physics {

struct SkySampling {
  double min_samples = 40, max_samples = 40;  // Hillaire 2020's RayMarchMinMaxSPP: 4, 14
  double full_samples_length = 100e3;         // m: rays this long or longer take max_samples
  double sample_offset = 0.5;                 // where in its step each sample sits (Hillaire 2020: 0.3)
  // The fraction of the sun that reaches the sample at distance t (m) along the ray: the
  // clouds' shadow (include/atmosphere_sky.glsl's sun-visibility hook). It dims the single
  // scattering only, not Ψ_ms. Empty: 1.
  std::function<double(double t)> sun_visibility = {};
};

// Ψ_ms(r, mu_s) for a sun of unit illuminance; empty for single scattering alone.
using MultiscatteringTerm = std::function<Vec3(double r, double mu_s)>;

Vec3 sky_scattering(const Atmosphere& atmosphere, double r, double mu, double mu_s, double nu,
                    const MultiscatteringTerm& multiscattering = {}, SkySampling sampling = {});

// The same over the first `length` m of the ray (aerial perspective: the air between the
// camera and a point), with the ray's transmittance over them.
struct ScatteringAlong {
  Vec3 radiance{0, 0, 0};
  Vec3 transmittance{1, 1, 1};
};
ScatteringAlong scattering_along(const Atmosphere& atmosphere, double r, double mu, double mu_s, double nu, double length,
                                 const MultiscatteringTerm& multiscattering = {}, SkySampling sampling = {});

// nu from a sky-view texel's direction: the view's zenith cosine mu and the cosine of its
// azimuth from the sun's, for a sun at zenith cosine mu_s (Hillaire 2020, SkyViewLut's frame).
double view_sun_cosine(double mu, double cos_azimuth, double mu_s);

// Where the scene's camera is in the planet's frame (Atmosphere: the planet's centre
// straight below the scene's origin, bottom_radius + origin_altitude down): its radius, its
// local zenith, the direction toward the sun (the atmosphere's sun light, against its
// direction of travel; none when the atmosphere has no sun) and the sun's zenith cosine there.
struct AtmosphereView {
  double r = 0;
  Vec3 up{0, 1, 0};
  Vec3 toward_sun{0, 1, 0};
  double mu_s = -1;
  bool has_sun = false;
};
AtmosphereView atmosphere_view(const Scene& scene);

// A world direction as the sky-view LUT holds it around the camera: its zenith cosine and
// the cosine of its azimuth from the sun's (1 where either is vertical).
SkyViewDirection sky_view_direction(const AtmosphereView& view, const Vec3& direction);

// The radiance of the sun's disk per unit irradiance: a uniform disk of angular radius α
// gives E = L π sin²α on a surface facing it, so L = E / (π sin²α).
double sun_disk_radiance_scale(double angular_radius);

// Limb darkening of the sun's disk at `rho` = sin θ / sin α (θ from its centre, α its
// angular radius): Hillaire 2016 ("Physically Based Sky, Atmosphere and Cloud Rendering
// in Frostbite", appendix B), after Neckel & Labs 1994 / Hestroffer & Magnan 1998:
// I(μ)/I(1) = 1 − u(1 − μ^a), u = 1, a = (0.397, 0.503, 0.652) at 680, 550 and 440 nm,
// μ = √(1 − ρ²) — divided by its mean over the disk's projected solid angle
// (2π sin θ d(sin θ) = π sin²α · 2ρ dρ), ∫₀¹ μ^a 2μ dμ = 2 / (a + 2), so that the disk's
// irradiance stays E. 0 outside the disk (ρ > 1).
Vec3 limb_darkening(double rho);

// The sun's disk per unit E in a unit world `direction`: sun_disk_radiance_scale within its
// angular radius (times limb_darkening when asked), times the transmittance toward it from
// the camera — from where the ray enters the atmosphere for a camera above it, 1 when the
// ray misses the atmosphere —; 0 outside the disk or where the ground is in the way.
Vec3 sun_disk_radiance(const Atmosphere& atmosphere, const AtmosphereView& view, const Vec3& direction, bool limb_darkened = false);

// The Lambertian ground's radiance per unit E where the sun's zenith cosine is mu_s
// (Bruneton 2017's ground radiance, albedo/π × its irradiance): the sun through the air,
// T_sun · max(mu_s, 0), and the sky's π·Ψ_ms (the isotropic ambient of
// physics/atmosphere_lighting.h; `psi` = Ψ_ms at the ground, 0 for the sun alone).
Vec3 ground_radiance(const Atmosphere& atmosphere, double mu_s, const Vec3& psi);

// The ground seen from inside the atmosphere (view.r at most the top's) in a unit world
// `direction`: ground_radiance times the air's transmittance to it; 0 where the ray misses
// the ground. Drawn beside a sky-view LUT, which holds the air's in-scattering alone.
Vec3 seen_ground_radiance(const Atmosphere& atmosphere, const AtmosphereView& view, const Vec3& direction,
                          const MultiscatteringTerm& multiscattering = {});

// What the camera sees in a unit world `direction` where no surface of the scene is, by a
// march along the pixel's own ray (Hillaire 2020's RenderSkyRayMarching path, no sky-view
// LUT), per unit E: a camera above the atmosphere starts where its ray enters the top
// (MoveToTopAtmosphere) and sees black space where it misses it; the air's in-scattering
// along the ray (scattering_along); where the ray ends on the ground, the ground's
// radiance (ground_radiance) times the air's transmittance to it; the sun's disk
// (sun_disk_radiance). The camera's radius is view.r as it is (not clamped to the top).
struct SkyViewOptions {
  SkySampling sampling;
  bool sun_disk = true;
  bool limb_darkening = false;
  bool ground = true;
};
Vec3 marched_sky_radiance(const Atmosphere& atmosphere, const AtmosphereView& view, const Vec3& direction,
                          const MultiscatteringTerm& multiscattering = {}, const SkyViewOptions& options = {});

}  // namespace volgraph::physics
