// Bruneton & Neyret 2008 / Bruneton 2017 ("Precomputed Atmospheric Scattering", and its
// reimplementation ebruneton/precomputed_atmospheric_scattering, atmosphere/functions.glsl):
// the parametrisations of the precomputed tables and the maths of their lookups. CPU twin of
// shaders/include/atmosphere_bruneton.glsl — change both together.
// - Scattering: a 4D function of (r, mu, mu_s, nu) in a 3D texture, nu and mu_s packed in x
//   (x = nu_index · mu_s_size + mu_s texel), mu in y with the horizon at v = 1/2 (rays that
//   hit the ground below it, those that reach the top above it), r in z. Each texel holds
//   the scattering for a sun of unit irradiance (E = 1) without the phase functions:
//   Rayleigh (plus the higher orders divided by the Rayleigh phase) in rgb. Single Mie
//   (rgb) is a table of its own, the same shape (Bruneton 2017 without
//   COMBINED_SCATTERING_TEXTURES: no extrapolation of its green and blue from its red).
// - Irradiance: the sky's irradiance on a horizontal surface (orders ≥ 1 of the light
//   reaching it indirectly) by (r, mu_s), both affine.
// The transmittance table is physics/atmosphere_lut.h's (the same parametrisation).
#pragma once

#include <functional>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/atmosphere_lut.h"

namespace volgraph::physics {

// The smallest sun zenith cosine the scattering table holds: cos 120°, Bruneton 2017's
// demo (max_sun_zenith_angle for 32-bit textures); below it the sun's light is nil.
constexpr double kBrunetonMuSMin = -0.5;

// Texels per parameter of the scattering table (Bruneton 2017's defaults: 8 × 32 × 128 × 32,
// a 256 × 128 × 32 texture) and of the irradiance table (64 × 16).
struct BrunetonTableSize {
  int nu = 8, mu_s = 32, mu = 128, r = 32;
  int irradiance_width = 64, irradiance_height = 16;
  int width() const { return nu * mu_s; }
};

// The 4D texture coordinate (Bruneton 2017, GetScatteringTextureUvwzFromRMuMuSNu's vec4:
// u_nu, u_mu_s, u_mu, u_r), each in [0, 1].
struct ScatteringUvwz {
  double nu = 0, mu_s = 0, mu = 0, r = 0;
};
struct ScatteringParams {
  double r = 0, mu = 0, mu_s = 0, nu = 0;
  bool ray_hits_ground = false;
};

// Bruneton 2017, GetScatteringTextureUvwzFromRMuMuSNu (r in [bottom, top]).
ScatteringUvwz scattering_uvwz(const Atmosphere& atmosphere, double r, double mu, double mu_s, double nu, bool ray_hits_ground,
                               const BrunetonTableSize& size);
// Bruneton 2017, GetRMuMuSNuFromScatteringTextureUvwz.
ScatteringParams scattering_params(const Atmosphere& atmosphere, const ScatteringUvwz& uvwz, const BrunetonTableSize& size);
// Bruneton 2017, GetRMuMuSNuFromScatteringTextureFragCoord: the parameters texel (x, y, z)
// holds, nu clamped to the range mu and mu_s allow.
ScatteringParams scattering_texel_params(const Atmosphere& atmosphere, int x, int y, int z, const BrunetonTableSize& size);

// The two 3D texture coordinates a 4D lookup blends (Bruneton 2017, GetScattering: the nu
// slices either side, `lerp` of the way from the first to the second).
struct ScatteringLookup {
  double x0 = 0, x1 = 0, y = 0, z = 0, lerp = 0;
};
ScatteringLookup scattering_lookup_coords(const ScatteringUvwz& uvwz, const BrunetonTableSize& size);

// Bruneton 2017, GetIrradianceTextureUvFromRMuS / GetRMuSFromIrradianceTextureUv.
LutUv irradiance_uv(const Atmosphere& atmosphere, double r, double mu_s, const BrunetonTableSize& size);
RadiusAndMuS irradiance_r_mu_s(const Atmosphere& atmosphere, LutUv uv, const BrunetonTableSize& size);

// A table read back from the GPU (or filled on the CPU): rgba texels, x fastest. Sampled
// as the shaders do, bilinear / trilinear between texel centres, clamped at the edges.
struct BrunetonTable {
  int width = 0, height = 0, depth = 1;
  std::vector<float> rgba;  // width · height · depth · 4
  std::array<double, 4> texel(int x, int y, int z = 0) const;
  std::array<double, 4> sample(double u, double v, double w = 0.5) const;
  // A scattering table's lookup: as `sample`, but geometric between two x (mu_s) texels
  // whose channel is positive (atmosphere_bruneton.glsl's bruneton_mix_mu_s).
  std::array<double, 4> sample_scattering(double u, double v, double w) const;

 private:
  std::array<double, 4> blended(double u, double v, double w, bool geometric_x) const;
};

// The transmittance to the top of the atmosphere from (r, mu), mu at or above the horizon
// (physics::transmittance_to_top, or the LUT read back).
using TransmittanceToTop = std::function<Vec3(double r, double mu)>;

// What the lookups read.
struct BrunetonTables {
  BrunetonTableSize size;
  const BrunetonTable* scattering = nullptr;             // size.width() × mu × r: Rayleigh + orders ≥ 2 (rgb)
  const BrunetonTable* single_mie_scattering = nullptr;  // the same shape: single Mie (rgb)
  const BrunetonTable* irradiance = nullptr;  // irradiance_width × irradiance_height
  TransmittanceToTop transmittance;
};

// Bruneton 2017, GetTransmittance: between (r, mu) and the point d along its ray, from two
// transmittances to the top (their ratio, reversed for a ray that hits the ground).
Vec3 transmittance_between(const Atmosphere& atmosphere, const TransmittanceToTop& transmittance, double r, double mu, double d,
                           bool ray_hits_ground);
// Bruneton 2017, ComputeSingleScattering: Rayleigh and Mie single scattering toward (r, mu)
// from its ray to the nearest boundary for a sun of unit irradiance, without the phase
// functions (what a single-scattering texel holds), by the trapezoidal rule over
// `samples` intervals (Bruneton 2017: 50).
struct SingleScattering {
  Vec3 rayleigh{0, 0, 0}, mie{0, 0, 0};
};
// volgraph's default trapezoids for single scattering, not Bruneton 2017's 50: the single Mie
// integrand (scale height 1.2 km) needs them along rays of 100 km; beside the sun the sky's
// worst pixel falls from 5.5 % to 0.28 % (tests/accuracy/atmosphere_sky_accuracy_test.cpp).
inline constexpr int kSingleScatteringSamples = 200;
SingleScattering single_scattering(const Atmosphere& atmosphere, const TransmittanceToTop& transmittance, const ScatteringParams& p,
                                   int samples = kSingleScatteringSamples);
// Bruneton 2017, ComputeDirectIrradiance: the sun's irradiance on a horizontal surface at
// (r, mu_s) for a sun of unit irradiance (the average cosine over its visible disk).
Vec3 direct_irradiance(const Atmosphere& atmosphere, const TransmittanceToTop& transmittance, double r, double mu_s);

// A lookup's result: radiance per unit E toward the camera and the transmittance.
struct BrunetonRadiance {
  Vec3 radiance{0, 0, 0};
  Vec3 transmittance{1, 1, 1};
};
// Bruneton 2017, GetSkyRadiance (no light shafts, separate single Mie): the sky along unit `view_ray` from
// `camera` (planet frame, the centre at the origin; above the top it enters first),
// toward unit `sun_direction`; the transmittance to the ray's end (0 where it hits the ground).
BrunetonRadiance sky_radiance(const Atmosphere& atmosphere, const BrunetonTables& tables, const Vec3& camera, const Vec3& view_ray,
                              const Vec3& sun_direction);
// Bruneton 2017, GetSkyRadianceToPoint (no light shafts, separate single Mie): the air between `camera` and `point`.
BrunetonRadiance sky_radiance_to_point(const Atmosphere& atmosphere, const BrunetonTables& tables, const Vec3& camera,
                                       const Vec3& point, const Vec3& sun_direction);
// Bruneton 2017, GetSunAndSkyIrradiance: at `point` on a surface of unit `normal`, the sun's
// (through its transmittance) and the sky's (the table's, scaled by (1 + n·up)/2) irradiance.
struct SunAndSkyIrradiance {
  Vec3 sun{0, 0, 0}, sky{0, 0, 0};
};
SunAndSkyIrradiance sun_and_sky_irradiance(const Atmosphere& atmosphere, const BrunetonTables& tables, const Vec3& point,
                                           const Vec3& normal, const Vec3& sun_direction);

}  // namespace volgraph::physics
