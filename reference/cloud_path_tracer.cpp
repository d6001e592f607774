#include "reference/cloud_path_tracer.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/cloud_lighting.h"
#include "physics/phase.h"
#include "physics/vec3.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::scaled;

// The distance to the next tentative collision against the majorant (exponential).
double free_flight(double majorant, CloudRandom& random) { return -std::log1p(-random.uniform()) / majorant; }

// Delta tracking from p along d over [t, t_end): the first real collision's distance, or a
// value ≥ t_end where the ray leaves first.
double delta_track(const CloudWalkMedium& medium, const Vec3& p, const Vec3& d, double t, double t_end, CloudRandom& random) {
  const double majorant = medium.majorant();
  for (;;) {
    t += free_flight(majorant, random);
    if (t >= t_end) return t_end;
    if (random.uniform() * majorant < medium.sigma_t(add(p, scaled(d, t)))) return t;
  }
}

// Ratio tracking from p toward the sun to where the medium ends: an unbiased estimate of the
// sun's transmittance.
double ratio_track(const CloudWalkMedium& medium, const Vec3& p, const Vec3& to_sun, CloudRandom& random) {
  const double majorant = medium.majorant(), t_end = medium.exit_distance(p, to_sun);
  double transmittance = 1, t = 0;
  for (;;) {
    t += free_flight(majorant, random);
    if (t >= t_end) return transmittance;
    transmittance *= 1 - medium.sigma_t(add(p, scaled(to_sun, t))) / majorant;
    if (transmittance <= 0) return 0;
  }
}

// The sun's next-event weight at a collision x reached along d: p(θ) · T_sun, cosθ =
// to_sun · d as CloudReference (the light travels −to_sun, is scattered toward −d).
double sun_weight(const CloudWalkMedium& medium, const CloudWalkLight& light, const Vec3& x, const Vec3& d, CloudRandom& random) {
  if (!light.has_sun || medium.ground_hides_sun(x)) return 0;
  const double phase = physics::cloud_lighting::cloud_phase(float(dot(light.to_sun, d)), float(light.g_forward),
                                                           float(light.g_back), float(light.back_weight));
  return phase * ratio_track(medium, x, light.to_sun, random);
}

}  // namespace

// The adjoint walk: the light goes the other way, and HG is symmetric under that reversal.
Vec3 sample_cloud_phase(const CloudWalkLight& light, const Vec3& d, CloudRandom& random) {
  const double g = random.uniform() < std::clamp(light.back_weight, 0.0, 1.0) ? light.g_back : light.g_forward;
  const double cos_theta = physics::sample_hg_cosine(g, random.uniform());
  return physics::around(d, cos_theta, 2 * std::numbers::pi * random.uniform());
}

uint64_t cloud_pixel_seed(uint32_t i, uint32_t j, uint64_t base) { return splitmix64(base ^ splitmix64((uint64_t(j) << 32) | i)); }

double CloudLayerMedium::sigma_t(const Vec3& p) const { return clouds_.layer().extinction * clouds_.density(p); }

// cloud_base_density ≤ coverage (its remapped base in [0, 1] times the coverage) and erosion
// only lowers it (cloud_density.h), so extinction × min(coverage, 1) bounds σt.
double CloudLayerMedium::majorant() const {
  const CloudLayer& layer = clouds_.layer();
  return std::max(layer.extinction * std::clamp(layer.coverage, 0.0, 1.0), 1e-12);
}

double CloudLayerMedium::exit_distance(const Vec3& p, const Vec3& d) const {
  double t_in = 0, t_out = 0;
  return clouds_.segment(p, d, t_in, t_out) ? t_out : 0;
}

CloudWalkLight cloud_walk_light(const CloudReference& clouds) {
  const CloudReferenceSettings& k = clouds.settings();
  return {.has_sun = clouds.has_sun(), .to_sun = clouds.to_sun(), .sun_irradiance = clouds.sun_irradiance(), .ambient = k.ambient,
          .g_forward = k.g_forward, .g_back = k.g_back, .back_weight = k.back_weight};
}

CloudPath trace_cloud_path(const CloudWalkMedium& medium, const CloudWalkLight& light, const Vec3& origin, const Vec3& d0,
                           double t_in, double t_out, int bounces, CloudRandom& random) {
  CloudPath path;
  Vec3 p = origin, d = d0;
  double t = t_in, t_end = t_out;
  for (int order = 1; order <= bounces; ++order) {
    t = delta_track(medium, p, d, t, t_end, random);
    if (t >= t_end) break;  // left the medium
    p = add(p, scaled(d, t));
    // Albedo 1: the collision estimator's σs/σt is 1, the path's weight stays 1.
    const double sun = sun_weight(medium, light, p, d, random);
    path.by_order.push_back(sun);
    path.radiance = add(path.radiance, scaled(light.sun_irradiance, sun));
    if (order == 1) path.radiance = add(path.radiance, light.ambient);
    d = sample_cloud_phase(light, d, random);
    t = 0, t_end = medium.exit_distance(p, d);
  }
  return path;
}

CloudRadianceEstimate cloud_multiple_scattering(const CloudReference& clouds, const Vec3& direction, double surface,
                                                const CloudPathSettings& settings, uint64_t seed) {
  CloudRadianceEstimate out;
  double t_in = 0, t_out = 0;
  if (clouds.layer().coverage <= 0 || !clouds.segment(clouds.camera(), direction, t_in, t_out)) return out;
  t_out = std::min(t_out, std::min(surface, clouds.settings().max_distance));
  if (!(t_out > t_in)) return out;
  const CloudLayerMedium medium(clouds);
  const CloudWalkLight light = cloud_walk_light(clouds);
  CloudRandom random(seed);
  const int n = std::max(settings.samples, 1);
  Vec3 sum{0, 0, 0}, sum_squares{0, 0, 0};
  for (int s = 0; s < n; ++s) {
    const CloudPath path = trace_cloud_path(medium, light, clouds.camera(), direction, t_in, t_out, settings.bounces, random);
    for (size_t c = 0; c < 3; ++c) sum[c] += path.radiance[c], sum_squares[c] += path.radiance[c] * path.radiance[c];
    if (out.by_order.size() < path.by_order.size()) out.by_order.resize(path.by_order.size(), 0.0);
    for (size_t k = 0; k < path.by_order.size(); ++k) out.by_order[k] += path.by_order[k] / n;
  }
  for (size_t c = 0; c < 3; ++c) {
    const double mean = sum[c] / n, variance = std::max(sum_squares[c] / n - mean * mean, 0.0);
    out.radiance[c] = mean;
    out.standard_error[c] = std::sqrt(variance / std::max(n - 1, 1));
  }
  return out;
}

}  // namespace volgraph::reference
