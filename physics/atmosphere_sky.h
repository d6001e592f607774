// The light the atmosphere scatters toward a viewer along a ray (Hillaire 2020 §5.3, the
// sky-view LUT's integral; §4 for the scattering): from (r, mu) to the ray's end at the top
// of the atmosphere or the ground, for a sun of unit illuminance at zenith cosine mu_s
// whose direction makes cosine nu with the ray's,
//   L = ∫ T(0, t) [σs_R(t) p_R(nu) + σs_M(t) p_M(nu)) T_sun(t) + σs(t) Ψ_ms(t)] dt
// with Hillaire's sampling: between 4 and 14 samples (more for longer rays: 14 from
// 100 km), quadratically spaced ((s/n)² of the length), each at 0.3 of its step, and the
// energy-conserving step (S − S·T)/σt. Ψ_ms is the multiple-scattering term
// (atmosphere_multiscattering.h), or none for single scattering alone. CPU twin of
// shaders/include/atmosphere_sky.glsl (which reads T_sun and Ψ_ms from their LUTs) —
// change both together.
#pragma once

#include <functional>

#include "graph/scene/scene.h"
#include "physics/atmosphere_lut.h"

namespace volgraph::physics {

struct SkySampling {
  double min_samples = 4, max_samples = 14;  // Hillaire 2020's RayMarchMinMaxSPP
  double full_samples_length = 100e3;        // m: rays this long or longer take max_samples
};

// Ψ_ms(r, mu_s) for a sun of unit illuminance; empty for single scattering alone.
using MultiscatteringTerm = std::function<Vec3(double r, double mu_s)>;

Vec3 sky_scattering(const Atmosphere& atmosphere, double r, double mu, double mu_s, double nu,
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

// The sun's disk per unit E in a unit world `direction`: 1 / (π α²) within its angular
// radius α (a uniform disk of that radius gives irradiance E), times the transmittance
// toward it from the camera; 0 outside the disk or where the ground is in the way.
Vec3 sun_disk_radiance(const Atmosphere& atmosphere, const AtmosphereView& view, const Vec3& direction);

}  // namespace volgraph::physics
