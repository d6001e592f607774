#include "physics/atmosphere_bruneton.h"

#include <algorithm>
#include <cmath>

#include "physics/atmosphere.h"
#include "physics/phase.h"
#include "physics/lighting.h"
#include "physics/vec3.h"

namespace volgraph::physics {
namespace {

double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double length3(const Vec3& a) { return std::sqrt(dot3(a, a)); }
Vec3 axpy(const Vec3& x, double s, const Vec3& y) { return {x[0] + s * y[0], x[1] + s * y[1], x[2] + s * y[2]}; }

double clamp_cosine(double mu) { return std::clamp(mu, -1.0, 1.0); }
// Bruneton 2017, ClampRadius.
double clamp_radius(const Atmosphere& a, double r) { return std::clamp(r, a.bottom_radius, a.top_radius); }

// H = √(top² − bottom²) and ρ = √(r² − bottom²), from the altitudes (physics/atmosphere.h).
double horizon_to_top(const Atmosphere& a) { return std::sqrt(std::max(sphere_constant_term(a.top_radius, a.bottom_radius), 0.0)); }
double distance_to_horizon(const Atmosphere& a, double r) { return std::sqrt(std::max(sphere_constant_term(r, a.bottom_radius), 0.0)); }

// Bruneton 2017, DistanceToBottomAtmosphereBoundary for a ray known to hit the ground.
double ground_distance(const Atmosphere& a, double r, double mu) {
  return std::max(sphere_near_root(r * mu, sphere_constant_term(r, a.bottom_radius)), 0.0);
}

// Bruneton 2017, DistanceToNearestAtmosphereBoundary.
double nearest_boundary(const Atmosphere& a, double r, double mu, bool ray_hits_ground) {
  return ray_hits_ground ? ground_distance(a, r, mu) : distance_to_top(a, r, mu);
}

// Bruneton 2017, GetScatteringTextureUvwzFromRMuMuSNu's A: the mu_s mapping's constant.
double mu_s_mapping_constant(const Atmosphere& a) {
  const double d_min = a.top_radius - a.bottom_radius, d_max = horizon_to_top(a);
  return (distance_to_top(a, a.bottom_radius, kBrunetonMuSMin) - d_min) / (d_max - d_min);
}

// The transmittance to the top at mu clamped to the horizon (the table's domain).
Vec3 top_transmittance(const Atmosphere& a, const TransmittanceToTop& t, double r, double mu) {
  return t(r, std::max(mu, mu_horizon(a, r)));
}

// Bruneton 2017, GetTransmittanceToSun.
Vec3 sun_transmittance_from(const Atmosphere& a, const TransmittanceToTop& t, double r, double mu_s) {
  const double fraction = sun_visible_fraction(a, r, mu_s);
  if (fraction <= 0) return {0, 0, 0};
  return times(top_transmittance(a, t, r, mu_s), fraction);
}

// Bruneton 2017, GetScattering: a table's rgb at (r, mu, mu_s, nu), two trilinear lookups
// blended in nu.
Vec3 table_scattering(const Atmosphere& a, const BrunetonTableSize& size, const BrunetonTable& table, double r, double mu, double mu_s,
                      double nu, bool ray_hits_ground) {
  const ScatteringUvwz uvwz = scattering_uvwz(a, r, mu, mu_s, nu, ray_hits_ground, size);
  const ScatteringLookup at = scattering_lookup_coords(uvwz, size);
  const std::array<double, 4> s0 = table.sample_scattering(at.x0, at.y, at.z), s1 = table.sample_scattering(at.x1, at.y, at.z);
  Vec3 out{};
  for (size_t c = 0; c < 3; ++c) out[c] = s0[c] * (1 - at.lerp) + s1[c] * at.lerp;
  return out;
}

// Bruneton 2017, GetSkyRadiance's two lookups (separate textures): the Rayleigh + orders ≥ 2
// and the single Mie scattering at (r, mu, mu_s, nu).
struct RayleighAndMie {
  Vec3 rayleigh, mie;
};
RayleighAndMie scattering_at(const Atmosphere& a, const BrunetonTables& tables, double r, double mu, double mu_s, double nu,
                             bool ray_hits_ground) {
  return {table_scattering(a, tables.size, *tables.scattering, r, mu, mu_s, nu, ray_hits_ground),
          table_scattering(a, tables.size, *tables.single_mie_scattering, r, mu, mu_s, nu, ray_hits_ground)};
}

// Rayleigh rgb · p_R(nu) + Mie rgb · p_M(nu) (Bruneton 2017, GetSkyRadiance's return).
Vec3 with_phases(const Atmosphere& a, const Vec3& rayleigh, const Vec3& mie, double nu) {
  return axpy(times(rayleigh, phase_rayleigh(nu)), mie_phase(a, nu), mie);
}


}  // namespace

ScatteringUvwz scattering_uvwz(const Atmosphere& a, double r, double mu, double mu_s, double nu, bool ray_hits_ground,
                               const BrunetonTableSize& size) {
  const double H = horizon_to_top(a), rho = distance_to_horizon(a, r);
  ScatteringUvwz out;
  out.r = texture_coord_from_unit_range(H > 0 ? std::clamp(rho / H, 0.0, 1.0) : 0.0, size.r);
  if (ray_hits_ground) {
    // The distance to the ground between its extremes, r − bottom (mu = −1) and ρ (the horizon).
    const double d = ground_distance(a, r, mu), d_min = r - a.bottom_radius, d_max = rho;
    const double x = d_max == d_min ? 0.0 : std::clamp((d - d_min) / (d_max - d_min), 0.0, 1.0);
    out.mu = 0.5 - 0.5 * texture_coord_from_unit_range(x, size.mu / 2);
  } else {
    // The distance to the top between its extremes, top − r (mu = 1) and ρ + H (the horizon).
    const double d = distance_to_top(a, r, mu), d_min = a.top_radius - r, d_max = rho + H;
    const double x = d_max == d_min ? 0.0 : std::clamp((d - d_min) / (d_max - d_min), 0.0, 1.0);
    out.mu = 0.5 + 0.5 * texture_coord_from_unit_range(x, size.mu / 2);
  }
  // mu_s through the ground's distance to the top toward the sun, with Bruneton 2017's
  // ad-hoc max(1 − a/A, 0) / (1 + a): 0 at mu_s_min, 1 at the zenith, steep at the horizon.
  const double d_min = a.top_radius - a.bottom_radius, d_max = H;
  const double x_a = (distance_to_top(a, a.bottom_radius, mu_s) - d_min) / (d_max - d_min);
  const double A = mu_s_mapping_constant(a);
  out.mu_s = texture_coord_from_unit_range(std::clamp(std::max(1 - x_a / A, 0.0) / (1 + x_a), 0.0, 1.0), size.mu_s);
  out.nu = std::clamp((nu + 1) / 2, 0.0, 1.0);
  return out;
}

ScatteringParams scattering_params(const Atmosphere& a, const ScatteringUvwz& uvwz, const BrunetonTableSize& size) {
  const double H = horizon_to_top(a);
  const double rho = H * std::clamp(unit_range_from_texture_coord(uvwz.r, size.r), 0.0, 1.0);
  ScatteringParams p;
  p.r = std::sqrt(rho * rho + a.bottom_radius * a.bottom_radius);
  if (uvwz.mu < 0.5) {
    // GetRMuMuSNuFromScatteringTextureUvwz, the ground half: mu from the distance to the ground.
    const double d_min = p.r - a.bottom_radius, d_max = rho;
    const double d = d_min + (d_max - d_min) * std::clamp(unit_range_from_texture_coord(1 - 2 * uvwz.mu, size.mu / 2), 0.0, 1.0);
    p.mu = d == 0 ? -1.0 : clamp_cosine(-(rho * rho + d * d) / (2 * p.r * d));
    p.ray_hits_ground = true;
  } else {
    // The sky half: mu from the distance to the top.
    const double d_min = a.top_radius - p.r, d_max = rho + H;
    const double d = d_min + (d_max - d_min) * std::clamp(unit_range_from_texture_coord(2 * uvwz.mu - 1, size.mu / 2), 0.0, 1.0);
    p.mu = d == 0 ? 1.0 : clamp_cosine((H * H - rho * rho - d * d) / (2 * p.r * d));
    p.ray_hits_ground = false;
  }
  const double x_mu_s = std::clamp(unit_range_from_texture_coord(uvwz.mu_s, size.mu_s), 0.0, 1.0);
  const double d_min = a.top_radius - a.bottom_radius, d_max = H;
  const double A = mu_s_mapping_constant(a);
  const double x_a = (A - x_mu_s * A) / (1 + x_mu_s * A);
  const double d = d_min + std::min(x_a, A) * (d_max - d_min);
  p.mu_s = d == 0 ? 1.0 : clamp_cosine((H * H - d * d) / (2 * a.bottom_radius * d));
  p.nu = clamp_cosine(uvwz.nu * 2 - 1);
  return p;
}

ScatteringParams scattering_texel_params(const Atmosphere& a, int x, int y, int z, const BrunetonTableSize& size) {
  // GetRMuMuSNuFromScatteringTextureFragCoord: frag_coord = texel + ½; nu's index and
  // mu_s's coordinate unpacked from x; nu by index over nu_size − 1 (both ends held).
  const int nu_index = x / size.mu_s, mu_s_index = x % size.mu_s;
  ScatteringUvwz uvwz;
  uvwz.nu = size.nu > 1 ? double(nu_index) / double(size.nu - 1) : 0.5;
  uvwz.mu_s = (mu_s_index + 0.5) / size.mu_s;
  uvwz.mu = (y + 0.5) / size.mu;
  uvwz.r = (z + 0.5) / size.r;
  ScatteringParams p = scattering_params(a, uvwz, size);
  // nu within the range the view and sun zenith cosines allow.
  const double spread = std::sqrt(std::max((1 - p.mu * p.mu) * (1 - p.mu_s * p.mu_s), 0.0));
  p.nu = std::clamp(p.nu, p.mu * p.mu_s - spread, p.mu * p.mu_s + spread);
  return p;
}

ScatteringLookup scattering_lookup_coords(const ScatteringUvwz& uvwz, const BrunetonTableSize& size) {
  // Bruneton 2017, GetScattering: the nu slices either side of u_nu · (nu_size − 1).
  const double coord = uvwz.nu * double(size.nu - 1);
  const double slice = std::min(std::floor(coord), double(std::max(size.nu - 2, 0)));
  ScatteringLookup out;
  out.lerp = std::clamp(coord - slice, 0.0, 1.0);
  out.x0 = (slice + uvwz.mu_s) / size.nu;
  out.x1 = (slice + 1 + uvwz.mu_s) / size.nu;
  out.y = uvwz.mu;
  out.z = uvwz.r;
  return out;
}

LutUv irradiance_uv(const Atmosphere& a, double r, double mu_s, const BrunetonTableSize& size) {
  const double x_r = std::clamp((r - a.bottom_radius) / (a.top_radius - a.bottom_radius), 0.0, 1.0);
  const double x_mu_s = std::clamp(mu_s * 0.5 + 0.5, 0.0, 1.0);
  return {texture_coord_from_unit_range(x_mu_s, size.irradiance_width), texture_coord_from_unit_range(x_r, size.irradiance_height)};
}

RadiusAndMuS irradiance_r_mu_s(const Atmosphere& a, LutUv uv, const BrunetonTableSize& size) {
  const double x_mu_s = std::clamp(unit_range_from_texture_coord(uv.u, size.irradiance_width), 0.0, 1.0);
  const double x_r = std::clamp(unit_range_from_texture_coord(uv.v, size.irradiance_height), 0.0, 1.0);
  return {a.bottom_radius + x_r * (a.top_radius - a.bottom_radius), clamp_cosine(2 * x_mu_s - 1)};
}

std::array<double, 4> BrunetonTable::texel(int x, int y, int z) const {
  x = std::clamp(x, 0, width - 1);
  y = std::clamp(y, 0, height - 1);
  z = std::clamp(z, 0, depth - 1);
  const size_t i = 4 * ((size_t(z) * size_t(height) + size_t(y)) * size_t(width) + size_t(x));
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

namespace {
// Two texels of one channel, `t` of the way from `low` to `high`: linear, or geometric where
// both are positive (the scattering tables' mu_s blend: atmosphere_bruneton.glsl's bruneton_mix_mu_s).
double blend(double low, double high, double t, bool geometric) {
  if (geometric && low > 0 && high > 0) return std::exp(std::log(low) * (1 - t) + std::log(high) * t);
  return low * (1 - t) + high * t;
}
}  // namespace

std::array<double, 4> BrunetonTable::blended(double u, double v, double w, bool geometric_x) const {
  // Between texel centres, clamped at the edges (the shaders' fetched filter).
  const double fx = u * width - 0.5, fy = v * height - 0.5, fz = w * depth - 0.5;
  const int x = int(std::floor(fx)), y = int(std::floor(fy)), z = int(std::floor(fz));
  const double tx = fx - x, ty = fy - y, tz = fz - z;
  std::array<double, 4> out{};
  for (int k = 0; k < 4; ++k) {
    const int dy = k & 1, dz = (k >> 1) & 1;
    const double weight = (dy ? ty : 1 - ty) * (depth > 1 ? (dz ? tz : 1 - tz) : (dz ? 0.0 : 1.0));
    if (weight == 0) continue;
    const std::array<double, 4> low = texel(x, y + dy, z + dz), high = texel(x + 1, y + dy, z + dz);
    for (size_t c = 0; c < 4; ++c) out[c] += weight * blend(low[c], high[c], tx, geometric_x && c < 3);
  }
  return out;
}

std::array<double, 4> BrunetonTable::sample(double u, double v, double w) const { return blended(u, v, w, false); }
std::array<double, 4> BrunetonTable::sample_scattering(double u, double v, double w) const { return blended(u, v, w, true); }

Vec3 transmittance_between(const Atmosphere& a, const TransmittanceToTop& t, double r, double mu, double d, bool ray_hits_ground) {
  // Bruneton 2017, GetTransmittance: T(r, mu) / T(r_d, mu_d), reversed for ground rays.
  const double r_d = clamp_radius(a, radius_at(r, mu, d));
  const double mu_d = clamp_cosine((r * mu + d) / r_d);
  const Vec3 near = ray_hits_ground ? top_transmittance(a, t, r_d, -mu_d) : top_transmittance(a, t, r, mu);
  const Vec3 far = ray_hits_ground ? top_transmittance(a, t, r, -mu) : top_transmittance(a, t, r_d, mu_d);
  Vec3 out{};
  for (size_t c = 0; c < 3; ++c) out[c] = far[c] > 0 ? std::min(near[c] / far[c], 1.0) : 0.0;
  return out;
}

SingleScattering single_scattering(const Atmosphere& a, const TransmittanceToTop& t, const ScatteringParams& p, int samples) {
  // Bruneton 2017, ComputeSingleScattering / ComputeSingleScatteringIntegrand (trapezoids).
  const double dx = nearest_boundary(a, p.r, p.mu, p.ray_hits_ground) / samples;
  Vec3 rayleigh{0, 0, 0}, mie{0, 0, 0};
  for (int i = 0; i <= samples; ++i) {
    const double d = i * dx;
    const double r_d = clamp_radius(a, radius_at(p.r, p.mu, d));
    const double mu_s_d = clamp_cosine((p.r * p.mu_s + d * p.nu) / r_d);
    const double altitude = std::max(altitude_at(a, p.r, p.mu, d), 0.0);
    const Vec3 transmittance =
        times(transmittance_between(a, t, p.r, p.mu, d, p.ray_hits_ground), sun_transmittance_from(a, t, r_d, mu_s_d));
    const double weight = (i == 0 || i == samples) ? 0.5 : 1.0;
    rayleigh = axpy(rayleigh, weight * profile_density(a.rayleigh_density, altitude), transmittance);
    mie = axpy(mie, weight * profile_density(a.mie_density, altitude), transmittance);
  }
  return {times(times(rayleigh, dx), a.rayleigh_scattering), times(times(mie, dx), a.mie_scattering)};
}

Vec3 direct_irradiance(const Atmosphere& a, const TransmittanceToTop& t, double r, double mu_s) {
  // Bruneton 2017, ComputeDirectIrradiance: the cosine averaged over the sun's visible disk.
  const double alpha = a.sun_angular_radius;
  const double cosine = mu_s < -alpha ? 0.0 : (mu_s > alpha ? mu_s : (mu_s + alpha) * (mu_s + alpha) / (4 * alpha));
  return times(top_transmittance(a, t, r, mu_s), cosine);
}

BrunetonRadiance sky_radiance(const Atmosphere& a, const BrunetonTables& tables, const Vec3& camera_in, const Vec3& view_ray,
                              const Vec3& sun_direction) {
  // Bruneton 2017, GetSkyRadiance: a camera in space first moves to the top along its ray.
  Vec3 camera = camera_in;
  double r = length3(camera);
  BrunetonRadiance out;
  if (r > a.top_radius) {
    const std::optional<double> enter = enter_atmosphere(a, r, dot3(camera, view_ray) / r);
    if (!enter) return out;
    camera = axpy(camera, *enter, view_ray);
    r = a.top_radius;
  }
  r = clamp_radius(a, r);
  const double mu = clamp_cosine(dot3(camera, view_ray) / length3(camera));
  const double mu_s = clamp_cosine(dot3(camera, sun_direction) / length3(camera));
  const double nu = clamp_cosine(dot3(view_ray, sun_direction));
  const bool hits_ground = ray_hits_ground(a, r, mu);
  out.transmittance = hits_ground ? Vec3{0, 0, 0} : top_transmittance(a, tables.transmittance, r, mu);
  const RayleighAndMie s = scattering_at(a, tables, r, mu, mu_s, nu, hits_ground);
  out.radiance = with_phases(a, s.rayleigh, s.mie, nu);
  return out;
}

BrunetonRadiance sky_radiance_to_point(const Atmosphere& a, const BrunetonTables& tables, const Vec3& camera_in, const Vec3& point,
                                       const Vec3& sun_direction) {
  // Bruneton 2017, GetSkyRadianceToPoint: S(camera) − T · S(point), both to the boundary.
  Vec3 camera = camera_in;
  const Vec3 to_point = axpy(point, -1, camera);
  const double distance = length3(to_point);
  BrunetonRadiance out;
  if (!(distance > 0)) return out;
  const Vec3 view_ray = times(to_point, 1 / distance);
  double r = length3(camera);
  if (r > a.top_radius) {
    const std::optional<double> enter = enter_atmosphere(a, r, dot3(camera, view_ray) / r);
    if (!enter) return out;
    camera = axpy(camera, *enter, view_ray);
  }
  r = clamp_radius(a, length3(camera));
  const double mu = clamp_cosine(dot3(camera, view_ray) / length3(camera));
  const double mu_s = clamp_cosine(dot3(camera, sun_direction) / length3(camera));
  const double nu = clamp_cosine(dot3(view_ray, sun_direction));
  const double d = length3(axpy(point, -1, camera));
  const bool hits_ground = ray_hits_ground(a, r, mu);
  out.transmittance = transmittance_between(a, tables.transmittance, r, mu, d, hits_ground);
  const RayleighAndMie s = scattering_at(a, tables, r, mu, mu_s, nu, hits_ground);
  const double r_p = clamp_radius(a, radius_at(r, mu, d));
  const double mu_p = clamp_cosine((r * mu + d) / r_p), mu_s_p = clamp_cosine((r * mu_s + d * nu) / r_p);
  const RayleighAndMie s_p = scattering_at(a, tables, r_p, mu_p, mu_s_p, nu, hits_ground);
  const Vec3 rayleigh = axpy(s.rayleigh, -1, times(out.transmittance, s_p.rayleigh));
  // Bruneton 2017's smoothstep on the single Mie term against artefacts below the horizon.
  const Vec3 mie = times(axpy(s.mie, -1, times(out.transmittance, s_p.mie)), smoothstep(0.0, 0.01, mu_s));
  out.radiance = with_phases(a, rayleigh, mie, nu);
  return out;
}

SunAndSkyIrradiance sun_and_sky_irradiance(const Atmosphere& a, const BrunetonTables& tables, const Vec3& point, const Vec3& normal,
                                           const Vec3& sun_direction) {
  // Bruneton 2017, GetSunAndSkyIrradiance (the table's irradiance is for a horizontal surface).
  const double r_point = length3(point);
  const double r = clamp_radius(a, r_point);
  const double mu_s = clamp_cosine(dot3(point, sun_direction) / r_point);
  const LutUv uv = irradiance_uv(a, r, mu_s, tables.size);
  const std::array<double, 4> sky = tables.irradiance->sample(uv.u, uv.v);
  const double tilt = (1 + dot3(normal, point) / r_point) * 0.5;
  SunAndSkyIrradiance out;
  out.sky = {sky[0] * tilt, sky[1] * tilt, sky[2] * tilt};
  out.sun = times(sun_transmittance_from(a, tables.transmittance, r, mu_s), std::max(dot3(normal, sun_direction), 0.0));
  return out;
}

}  // namespace volgraph::physics
