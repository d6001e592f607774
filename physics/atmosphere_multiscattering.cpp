#include "physics/atmosphere_multiscattering.h"

#include <algorithm>
#include <cmath>

#include "physics/atmosphere.h"
#include "physics/vec3.h"

namespace volgraph::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kIsotropicPhase = 1 / (4 * kPi);

// Direction k of `n`² uniform on the sphere (Hillaire 2020's LUT: θ = 2π (i + ½)/n around
// the zenith, cos φ = 1 − 2 (j + ½)/n): its zenith cosine mu and its cosine nu with the sun
// (whose direction is (√(1 − mu_s²), 0, mu_s) in the zenith's frame).
struct SphereDirection {
  double mu, nu;
};
SphereDirection sphere_direction(int i, int j, int n, double mu_s) {
  const double theta = 2 * kPi * (i + 0.5) / n;
  const double cos_phi = 1 - 2 * (j + 0.5) / n;
  const double sin_phi = std::sqrt(std::max(0.0, 1 - cos_phi * cos_phi));
  const double sun_x = std::sqrt(std::max(0.0, 1 - mu_s * mu_s));
  return {cos_phi, std::cos(theta) * sin_phi * sun_x + cos_phi * mu_s};
}


// One ray's L_f (unit sun) and its ∫σs T dt, marched from (r, mu) to its boundary.
MultiscatteringTerms march(const Atmosphere& a, double r, double mu, double mu_s, double nu, int steps) {
  MultiscatteringTerms out;
  const double length = distance_to_boundary(a, r, mu);
  const double dt = length / steps;
  Vec3 throughput{1, 1, 1};
  for (int s = 0; s < steps; ++s) {
    const double d = (s + 0.5) * dt;
    const double rd = radius_at(r, mu, d);
    const double altitude = altitude_at(a, r, mu, d);
    const Vec3 scattering = add(rayleigh_scattering_at(a, altitude), mie_scattering_at(a, altitude));
    const Vec3 extinction = extinction_at(a, altitude);
    const Vec3 sun = sun_transmittance(a, rd, mu_s_at(r, mu, mu_s, nu, d));
    for (size_t c = 0; c < 3; ++c) {
      const double step_transmittance = std::exp(-extinction[c] * dt);
      // Hillaire 2020 eq. 6 with the energy-conserving step: ∫ over the step of σs e^(−σt t).
      const double scattered_fraction = extinction[c] > 0 ? scattering[c] * (1 - step_transmittance) / extinction[c] : scattering[c] * dt;
      out.second_order[c] += throughput[c] * sun[c] * kIsotropicPhase * scattered_fraction;
      out.transfer[c] += throughput[c] * scattered_fraction;
      throughput[c] *= step_transmittance;
    }
  }
  if (!ray_hits_ground(a, r, mu)) return out;
  // The ground's Lambertian bounce where the ray ends on it (Hillaire 2020 §5.5).
  const double ground_mu_s = mu_s_at(r, mu, mu_s, nu, length);
  const Vec3 sun = sun_transmittance(a, a.bottom_radius, ground_mu_s);
  for (size_t c = 0; c < 3; ++c) {
    out.second_order[c] += throughput[c] * sun[c] * std::max(ground_mu_s, 0.0) * a.ground_albedo[c] / kPi;
  }
  return out;
}

}  // namespace

MultiscatteringTerms multiscattering_terms(const Atmosphere& atmosphere, double r, double mu_s, MultiscatteringSettings settings) {
  const int n = std::max(1, settings.directions_per_axis);
  const double weight = 4 * kPi / (n * n) * kIsotropicPhase;  // dω of each direction, times p_u
  MultiscatteringTerms total;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const SphereDirection w = sphere_direction(i, j, n, mu_s);
      const MultiscatteringTerms ray = march(atmosphere, r, w.mu, mu_s, w.nu, std::max(1, settings.steps));
      for (size_t c = 0; c < 3; ++c) {
        total.second_order[c] += ray.second_order[c] * weight;
        total.transfer[c] += ray.transfer[c] * weight;
      }
    }
  }
  return total;
}

Vec3 multiscattering(const Atmosphere& atmosphere, double r, double mu_s, MultiscatteringSettings settings) {
  const MultiscatteringTerms t = multiscattering_terms(atmosphere, r, mu_s, settings);
  Vec3 out;
  for (size_t c = 0; c < 3; ++c) out[c] = t.second_order[c] / std::max(1 - t.transfer[c], 1e-6);
  return out;
}

}  // namespace volgraph::physics
