// The atmosphere's LUT parametrisations: see atmosphere_lut.h.
#include "physics/atmosphere_lut.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/atmosphere.h"

namespace volgraph::physics {

double texture_coord_from_unit_range(double x, int texture_size) {
  return 0.5 / texture_size + x * (1 - 1.0 / texture_size);
}

double unit_range_from_texture_coord(double u, int texture_size) {
  return (u - 0.5 / texture_size) / (1 - 1.0 / texture_size);
}

namespace {

// H = √(top² − bottom²), the distance to the top along the ground's horizon, and
// ρ = √(r² − bottom²), the distance to the horizon from r (both from the altitudes).
double horizon_to_top(const Atmosphere& a) { return std::sqrt(std::max(sphere_constant_term(a.top_radius, a.bottom_radius), 0.0)); }
double distance_to_horizon(const Atmosphere& a, double r) { return std::sqrt(std::max(sphere_constant_term(r, a.bottom_radius), 0.0)); }

}  // namespace

// Bruneton 2017, GetTransmittanceTextureUvFromRMu: x_mu = (d − d_min) / (d_max − d_min) with
// d_min = top − r, d_max = ρ + H; x_r = ρ / H.
LutUv transmittance_lut_uv(const Atmosphere& a, double r, double mu, TransmittanceLutSize size) {
  const double H = horizon_to_top(a), rho = distance_to_horizon(a, r);
  const double d = distance_to_top(a, r, mu), d_min = a.top_radius - r, d_max = rho + H;
  const double x_mu = d_max > d_min ? std::clamp((d - d_min) / (d_max - d_min), 0.0, 1.0) : 0.0;
  const double x_r = H > 0 ? std::clamp(rho / H, 0.0, 1.0) : 0.0;
  return {texture_coord_from_unit_range(x_mu, size.width), texture_coord_from_unit_range(x_r, size.height)};
}

// Bruneton 2017, GetRMuFromTransmittanceTextureUv: ρ = H·x_r, d from x_mu, and mu from the
// law of cosines, (H² − ρ² − d²) / (2rd) (1 at d = 0).
RadiusAndMu transmittance_lut_r_mu(const Atmosphere& a, LutUv uv, TransmittanceLutSize size) {
  const double x_mu = std::clamp(unit_range_from_texture_coord(uv.u, size.width), 0.0, 1.0);
  const double x_r = std::clamp(unit_range_from_texture_coord(uv.v, size.height), 0.0, 1.0);
  const double H = horizon_to_top(a), rho = H * x_r;
  const double r = std::sqrt(rho * rho + a.bottom_radius * a.bottom_radius);
  const double d_min = a.top_radius - r, d_max = rho + H;
  const double d = d_min + x_mu * (d_max - d_min);
  if (d <= 0) return {r, 1.0};
  return {r, std::clamp((H * H - rho * rho - d * d) / (2 * r * d), -1.0, 1.0)};
}

// Hillaire 2020, GetMultipleScattering: (mu_s · 0.5 + 0.5, altitude / thickness).
LutUv multiscattering_lut_uv(const Atmosphere& a, double r, double mu_s, MultiscatteringLutSize size) {
  const double x_mu_s = std::clamp(mu_s * 0.5 + 0.5, 0.0, 1.0);
  const double x_r = std::clamp((r - a.bottom_radius) / (a.top_radius - a.bottom_radius), 0.0, 1.0);
  return {texture_coord_from_unit_range(x_mu_s, size.width), texture_coord_from_unit_range(x_r, size.height)};
}

RadiusAndMuS multiscattering_lut_r_mu_s(const Atmosphere& a, LutUv uv, MultiscatteringLutSize size) {
  const double x_mu_s = std::clamp(unit_range_from_texture_coord(uv.u, size.width), 0.0, 1.0);
  const double x_r = std::clamp(unit_range_from_texture_coord(uv.v, size.height), 0.0, 1.0);
  return {a.bottom_radius + x_r * (a.top_radius - a.bottom_radius), 2 * x_mu_s - 1};
}

namespace {

// β: the angle between the nadir and the horizon's direction (acos(ρ / r)); the horizon's
// zenith angle is π − β (Hillaire 2020, SkyViewLutParamsToUv).
double horizon_beta(const Atmosphere& a, double r) {
  return std::acos(std::clamp(distance_to_horizon(a, r) / std::max(r, a.bottom_radius), 0.0, 1.0));
}

}  // namespace

// Hillaire 2020, SkyViewLutParamsToUv: above the horizon v = (1 − √(1 − θ/θ_h)) / 2, below
// it v = (1 + √((θ − θ_h) / β)) / 2 (θ the view's zenith angle, θ_h = π − β);
// u = √(1/2 − cos_azimuth / 2).
LutUv sky_view_lut_uv(const Atmosphere& a, double r, SkyViewDirection direction, SkyViewLutSize size) {
  const double beta = horizon_beta(a, r), zenith_horizon = std::numbers::pi - beta;
  const double theta = std::acos(std::clamp(direction.mu, -1.0, 1.0));
  double v = 0;
  if (!ray_hits_ground(a, r, direction.mu)) {
    v = 0.5 * (1 - std::sqrt(std::max(1 - theta / zenith_horizon, 0.0)));
  } else {
    v = 0.5 * (1 + std::sqrt(std::clamp((theta - zenith_horizon) / beta, 0.0, 1.0)));
  }
  const double u = std::sqrt(std::clamp(0.5 - 0.5 * direction.cos_azimuth, 0.0, 1.0));
  return {texture_coord_from_unit_range(u, size.width), texture_coord_from_unit_range(v, size.height)};
}

// Hillaire 2020, UvToSkyViewLutParams.
SkyViewDirection sky_view_lut_direction(const Atmosphere& a, double r, LutUv uv, SkyViewLutSize size) {
  const double x = std::clamp(unit_range_from_texture_coord(uv.u, size.width), 0.0, 1.0);
  const double y = std::clamp(unit_range_from_texture_coord(uv.v, size.height), 0.0, 1.0);
  const double beta = horizon_beta(a, r), zenith_horizon = std::numbers::pi - beta;
  double theta = 0;
  if (y < 0.5) {
    const double above = 1 - 2 * y;
    theta = zenith_horizon * (1 - above * above);
  } else {
    const double below = 2 * y - 1;
    theta = zenith_horizon + beta * below * below;
  }
  return {std::cos(theta), 1 - 2 * x * x};
}

AerialSlice aerial_perspective_slice(double t, double distance, int slices) {
  const double half_slice = 0.5 / double(slices);
  const double w = std::max(t, 0.0) / distance;
  return {std::clamp(w, half_slice, 1 - half_slice), std::clamp(w / half_slice, 0.0, 1.0)};
}

}  // namespace volgraph::physics
