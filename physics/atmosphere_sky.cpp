#include "physics/atmosphere_sky.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "physics/atmosphere.h"
#include "physics/phase.h"

namespace volgraph::physics {

AtmosphereView atmosphere_view(const Scene& scene) {
  AtmosphereView view;
  if (!scene.atmosphere) return view;
  const Atmosphere& a = *scene.atmosphere;
  const Vec3& p = scene.camera.position;
  const Vec3 from_centre{p[0], p[1] + a.bottom_radius + a.origin_altitude, p[2]};
  view.r = std::sqrt(from_centre[0] * from_centre[0] + from_centre[1] * from_centre[1] + from_centre[2] * from_centre[2]);
  if (view.r > 0) view.up = {from_centre[0] / view.r, from_centre[1] / view.r, from_centre[2] / view.r};
  if (a.sun_light < 0 || size_t(a.sun_light) >= scene.lights.size()) return view;
  const Vec3& d = scene.lights[size_t(a.sun_light)].direction;
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0)) return view;
  view.toward_sun = {-d[0] / length, -d[1] / length, -d[2] / length};
  view.mu_s = std::clamp(view.up[0] * view.toward_sun[0] + view.up[1] * view.toward_sun[1] + view.up[2] * view.toward_sun[2], -1.0, 1.0);
  view.has_sun = true;
  return view;
}

SkyViewDirection sky_view_direction(const AtmosphereView& view, const Vec3& direction) {
  const Vec3& up = view.up;
  const double mu = std::clamp(direction[0] * up[0] + direction[1] * up[1] + direction[2] * up[2], -1.0, 1.0);
  const Vec3 across{direction[0] - mu * up[0], direction[1] - mu * up[1], direction[2] - mu * up[2]};
  const Vec3 sun_across{view.toward_sun[0] - view.mu_s * up[0], view.toward_sun[1] - view.mu_s * up[1], view.toward_sun[2] - view.mu_s * up[2]};
  const double lengths = std::sqrt((across[0] * across[0] + across[1] * across[1] + across[2] * across[2]) *
                                   (sun_across[0] * sun_across[0] + sun_across[1] * sun_across[1] + sun_across[2] * sun_across[2]));
  const double dot = across[0] * sun_across[0] + across[1] * sun_across[1] + across[2] * sun_across[2];
  return {mu, lengths > 1e-12 ? std::clamp(dot / lengths, -1.0, 1.0) : 1.0};
}

Vec3 limb_darkening(double rho) {
  if (rho > 1) return {0, 0, 0};
  // Hillaire 2016, appendix B (Neckel & Labs 1994): u = 1, a per channel at 680, 550, 440 nm.
  constexpr double a[3] = {0.397, 0.503, 0.652};
  const double mu = std::sqrt(std::max(0.0, 1 - rho * rho));
  Vec3 out{};
  for (size_t c = 0; c < 3; ++c) out[c] = std::pow(mu, a[c]) * (a[c] + 2) / 2;
  return out;
}

Vec3 sun_disk_radiance(const Atmosphere& atmosphere, const AtmosphereView& view, const Vec3& direction, bool limb_darkened) {
  const double cosine = std::clamp(direction[0] * view.toward_sun[0] + direction[1] * view.toward_sun[1] + direction[2] * view.toward_sun[2], -1.0, 1.0);
  if (!view.has_sun || cosine < std::cos(atmosphere.sun_angular_radius)) return {0, 0, 0};
  const double scale = sun_disk_radiance_scale(atmosphere.sun_angular_radius);
  const Vec3 limb = limb_darkened ? limb_darkening(std::sqrt(1 - cosine * cosine) / std::sin(atmosphere.sun_angular_radius)) : Vec3{1, 1, 1};
  double r = std::max(view.r, atmosphere.bottom_radius);
  double mu = std::clamp(direction[0] * view.up[0] + direction[1] * view.up[1] + direction[2] * view.up[2], -1.0, 1.0);
  if (r > atmosphere.top_radius) {
    const std::optional<double> entry = enter_atmosphere(atmosphere, r, mu);
    if (!entry) return {limb[0] * scale, limb[1] * scale, limb[2] * scale};  // Hillaire 2020: GetSunLuminance in space
    mu = mu_at(r, mu, *entry);
    r = atmosphere.top_radius;
  }
  if (ray_hits_ground(atmosphere, r, mu)) return {0, 0, 0};
  const Vec3 t = transmittance_to_top(atmosphere, r, mu);
  return {t[0] * limb[0] * scale, t[1] * limb[1] * scale, t[2] * limb[2] * scale};
}

double sun_disk_radiance_scale(double angular_radius) {
  const double s = std::sin(angular_radius);
  return 1 / (3.14159265358979323846 * s * s);
}

Vec3 ground_radiance(const Atmosphere& a, double mu_s, const Vec3& psi) {
  constexpr double pi = 3.14159265358979323846;
  const Vec3 sun = mu_s > 0 ? sun_transmittance(a, a.bottom_radius, mu_s) : Vec3{0, 0, 0};
  Vec3 out{};
  for (size_t c = 0; c < 3; ++c) out[c] = a.ground_albedo[c] * (sun[c] * std::max(mu_s, 0.0) / pi + psi[c]);
  return out;
}

Vec3 seen_ground_radiance(const Atmosphere& a, const AtmosphereView& view, const Vec3& direction, const MultiscatteringTerm& multiscattering) {
  const double r = std::clamp(view.r, a.bottom_radius, a.top_radius);
  const double mu = std::clamp(direction[0] * view.up[0] + direction[1] * view.up[1] + direction[2] * view.up[2], -1.0, 1.0);
  const std::optional<double> d = distance_to_ground(a, r, mu);
  if (!view.has_sun || !d) return {0, 0, 0};
  const double nu = std::clamp(direction[0] * view.toward_sun[0] + direction[1] * view.toward_sun[1] + direction[2] * view.toward_sun[2], -1.0, 1.0);
  const double ground_mu_s = mu_s_at(r, mu, view.mu_s, nu, *d);
  const Vec3 psi = multiscattering ? multiscattering(a.bottom_radius, ground_mu_s) : Vec3{0, 0, 0};
  const Vec3 ground = ground_radiance(a, ground_mu_s, psi);
  const Vec3 t = transmittance_to_boundary(a, r, mu);
  return {t[0] * ground[0], t[1] * ground[1], t[2] * ground[2]};
}

Vec3 marched_sky_radiance(const Atmosphere& a, const AtmosphereView& view, const Vec3& direction, const MultiscatteringTerm& multiscattering,
                          const SkyViewOptions& options) {
  if (!view.has_sun) return {0, 0, 0};
  const Vec3 disk = options.sun_disk ? sun_disk_radiance(a, view, direction, options.limb_darkening) : Vec3{0, 0, 0};
  double r = std::max(view.r, a.bottom_radius);
  double mu = std::clamp(direction[0] * view.up[0] + direction[1] * view.up[1] + direction[2] * view.up[2], -1.0, 1.0);
  const double nu = std::clamp(direction[0] * view.toward_sun[0] + direction[1] * view.toward_sun[1] + direction[2] * view.toward_sun[2], -1.0, 1.0);
  double mu_s = view.mu_s;
  if (r > a.top_radius) {  // Hillaire 2020, MoveToTopAtmosphere: start where the ray enters the top
    const std::optional<double> entry = enter_atmosphere(a, r, mu);
    if (!entry) return disk;
    mu_s = mu_s_at(r, mu, mu_s, nu, *entry);
    mu = mu_at(r, mu, *entry);
    r = a.top_radius;
  }
  const double length = distance_to_boundary(a, r, mu);
  const ScatteringAlong along = scattering_along(a, r, mu, mu_s, nu, length, multiscattering, options.sampling);
  Vec3 out{along.radiance[0] + disk[0], along.radiance[1] + disk[1], along.radiance[2] + disk[2]};
  if (!options.ground || !ray_hits_ground(a, r, mu)) return out;
  const double ground_mu_s = mu_s_at(r, mu, mu_s, nu, length);
  const Vec3 psi = multiscattering ? multiscattering(a.bottom_radius, ground_mu_s) : Vec3{0, 0, 0};
  const Vec3 ground = ground_radiance(a, ground_mu_s, psi);
  for (size_t c = 0; c < 3; ++c) out[c] += along.transmittance[c] * ground[c];
  return out;
}

double view_sun_cosine(double mu, double cos_azimuth, double mu_s) {
  const double sin_view = std::sqrt(std::max(0.0, 1 - mu * mu)), sin_sun = std::sqrt(std::max(0.0, 1 - mu_s * mu_s));
  return std::clamp(sin_view * sin_sun * cos_azimuth + mu * mu_s, -1.0, 1.0);
}

Vec3 sky_scattering(const Atmosphere& a, double r, double mu, double mu_s, double nu, const MultiscatteringTerm& multiscattering,
                    SkySampling sampling) {
  return scattering_along(a, r, mu, mu_s, nu, distance_to_boundary(a, r, mu), multiscattering, sampling).radiance;
}

ScatteringAlong scattering_along(const Atmosphere& a, double r, double mu, double mu_s, double nu, double length,
                                 const MultiscatteringTerm& multiscattering, SkySampling sampling) {
  ScatteringAlong out;
  Vec3& radiance = out.radiance;
  Vec3& throughput = out.transmittance;
  if (!(length > 0)) return out;
  // Hillaire 2020, IntegrateScatteredLuminance: a fractional sample count, the whole
  // samples over the part of the ray they cover, the last step stretched to its end.
  const double count = sampling.min_samples + (sampling.max_samples - sampling.min_samples) * std::clamp(length / sampling.full_samples_length, 0.0, 1.0);
  const double whole = std::max(1.0, std::floor(count));
  const double covered = length * whole / count;
  const double rayleigh_phase = phase_rayleigh(nu), mie = mie_phase(a, nu);
  double t = 0;
  for (int s = 0; s < int(whole); ++s) {
    const double t0 = covered * (s / whole) * (s / whole);
    double t1 = covered * ((s + 1) / whole) * ((s + 1) / whole);
    if (s + 1 == int(whole)) t1 = length;
    const double dt = t1 - t0;
    t = t0 + sampling.sample_offset * dt;
    const double rd = radius_at(r, mu, t), altitude = altitude_at(a, r, mu, t);
    const double sun_mu = mu_s_at(r, mu, mu_s, nu, t);
    const Vec3 rayleigh = rayleigh_scattering_at(a, altitude), mie_s = mie_scattering_at(a, altitude);
    const Vec3 extinction = extinction_at(a, altitude);
    Vec3 sun = sun_transmittance(a, rd, sun_mu);
    if (sampling.sun_visibility) {
      const double visible = sampling.sun_visibility(t);
      for (double& channel : sun) channel *= visible;
    }
    const Vec3 psi = multiscattering ? multiscattering(rd, sun_mu) : Vec3{0, 0, 0};
    for (size_t c = 0; c < 3; ++c) {
      const double source = (rayleigh[c] * rayleigh_phase + mie_s[c] * mie) * sun[c] + (rayleigh[c] + mie_s[c]) * psi[c];
      const double step_transmittance = std::exp(-extinction[c] * dt);
      // Hillaire 2020 §5.3: the source integrated over the step against its extinction.
      radiance[c] += throughput[c] * (extinction[c] > 0 ? source * (1 - step_transmittance) / extinction[c] : source * dt);
      throughput[c] *= step_transmittance;
    }
  }
  return out;
}

}  // namespace volgraph::physics
