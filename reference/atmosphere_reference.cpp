#include "reference/atmosphere_reference.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "physics/camera.h"
#include "physics/phase.h"
#include "reference/random.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::normalize;
using physics::scaled;
using physics::times;
using physics::largest;
using physics::exp_negative;
using physics::length_of;

constexpr double kPi = 3.14159265358979323846;


// The sun's disk as a uniform emitter (physics/atmosphere_sky.h).
Vec3 sun_radiance(const AtmosphereSun& sun) { return scaled(sun.irradiance, physics::sun_disk_radiance_scale(sun.angular_radius)); }

double altitude_of(const Atmosphere& a, const Vec3& p) { return std::max(0.0, length_of(p) - a.bottom_radius); }

// Inverse CDF of the Rayleigh phase's cosine, p(μ) ∝ 1 + μ²: the root of μ³ + 3μ = 8ξ − 4
// by Cardano's formula.
double sample_rayleigh_cosine(double xi) {
  const double z = 4 * xi - 2, root = std::sqrt(z * z + 1);
  return std::clamp(std::cbrt(z + root) + std::cbrt(z - root), -1.0, 1.0);
}

// Where a ray from `p` along unit `d` ends (the ground or the top), the atmosphere's
// parameters at p.
struct RayEnd {
  double length = 0;
  bool ground = false;
};

RayEnd ray_end(const Atmosphere& a, const Vec3& p, const Vec3& d) {
  const double r = std::min(length_of(p), a.top_radius), mu = dot(p, d) / length_of(p);
  const bool ground = physics::ray_hits_ground(a, r, mu);
  return {physics::distance_to_boundary(a, r, mu), ground};
}

// The optical depth along a segment, tabulated for drawing distances: τ̃ at kNodes + 1
// equally spaced points by the trapezoid rule, per channel (only the sampling densities
// come from it; the weights use physics' optical depth).
struct SegmentTable {
  static constexpr int kNodes = 128;
  double length = 0;
  std::vector<Vec3> tau;
};

SegmentTable tabulate(const Atmosphere& a, const Vec3& y, const Vec3& d, double length) {
  SegmentTable table{length, std::vector<Vec3>(SegmentTable::kNodes + 1, Vec3{0, 0, 0})};
  const double h = length / SegmentTable::kNodes;
  Vec3 previous = physics::extinction_at(a, altitude_of(a, y));
  for (int i = 1; i <= SegmentTable::kNodes; ++i) {
    const Vec3 e = physics::extinction_at(a, altitude_of(a, add(y, scaled(d, i * h))));
    for (int c = 0; c < 3; ++c) table.tau[size_t(i)][c] = table.tau[size_t(i - 1)][c] + 0.5 * (previous[c] + e[c]) * h;
    previous = e;
  }
  return table;
}

// Channel c's density of draw_distance at t: 0.9 × σ̃ e^(−τ̃) / (1 − e^(−τ̃(length))) + 0.1 ×
// uniform (uniform alone where the table has no extinction).
double distance_density(const SegmentTable& table, int c, double t) {
  constexpr int n = SegmentTable::kNodes;
  const double h = table.length / n, mass = -std::expm1(-table.tau.back()[c]);
  if (!(mass > 0)) return 1 / table.length;
  const int i = std::clamp(int(t / h), 0, n - 1);
  const double slope = (table.tau[size_t(i + 1)][c] - table.tau[size_t(i)][c]) / h;
  const double tau = table.tau[size_t(i)][c] + slope * (t - i * h);
  return 0.9 * slope * std::exp(-tau) / mass + 0.1 / table.length;
}

// A distance on [0, length] from channel c's distance_density.
double draw_distance(const SegmentTable& table, int c, Random& random) {
  constexpr int n = SegmentTable::kNodes;
  const double h = table.length / n, mass = -std::expm1(-table.tau.back()[c]);
  if (!(mass > 0) || random.uniform() < 0.1) return random.uniform() * table.length;
  const double target = -std::log1p(-random.uniform() * mass);
  int i = 0;
  while (i < n - 1 && table.tau[size_t(i + 1)][c] <= target) ++i;
  const double slope = (table.tau[size_t(i + 1)][c] - table.tau[size_t(i)][c]) / h;
  return std::clamp(i * h + (slope > 0 ? (target - table.tau[size_t(i)][c]) / slope : 0.0), 0.0, table.length);
}

// A path's throughput under one-sample multiple importance sampling over the channels
// (hero-wavelength spectral sampling, Wilkie et al. 2014, balance heuristic, Veach 1997
// §9.2): the path is drawn by the hero channel h's densities; f_c / p_h is kept per
// channel and p_j / p_h per strategy, and the estimate of channel c is
// f_c / ((p_0 + p_1 + p_2) / 3).
struct Throughput {
  Vec3 f_over_hero{1, 1, 1};
  Vec3 p_over_hero{1, 1, 1};
  Vec3 estimate() const { return scaled(f_over_hero, 3 / (p_over_hero[0] + p_over_hero[1] + p_over_hero[2])); }
  // One step: the integrand's factor per channel, and each strategy's density.
  void step(const Vec3& f, const Vec3& p, int hero) {
    for (int c = 0; c < 3; ++c) f_over_hero[c] *= f[c] / p[hero];
    for (int j = 0; j < 3; ++j) p_over_hero[j] *= p[j] / p[hero];
  }
  void scale(double s) { f_over_hero = scaled(f_over_hero, s); }
};

// A camera below the ground is moved up onto it (the models' LUTs clamp r the same way).
Vec3 on_or_above_ground(const Atmosphere& a, const Vec3& p) {
  const double r = length_of(p);
  if (r >= a.bottom_radius) return p;
  if (r <= 0) return {0, a.bottom_radius, 0};
  return scaled(p, a.bottom_radius / r);
}

// No scattering (a ray that misses the atmosphere): order 1, zero.
ScatteringOrders no_scattering() {
  ScatteringOrders none;
  none.radiance = {{0, 0, 0}};
  none.standard_error = {{0, 0, 0}};
  none.orders = 1;
  return none;
}

}  // namespace

std::optional<AtmosphereSun> scene_sun(const Atmosphere& a, const std::vector<Light>& lights) {
  if (a.sun_light < 0 || size_t(a.sun_light) >= lights.size()) return std::nullopt;
  const Light& light = lights[size_t(a.sun_light)];
  return AtmosphereSun{normalize(scaled(light.direction, -1)), light.irradiance, a.sun_angular_radius};
}

Vec3 planet_position(const Atmosphere& atmosphere, const Vec3& scene_point) {
  return add(scene_point, {0, atmosphere.bottom_radius + atmosphere.origin_altitude, 0});
}

AtmosphereReference::AtmosphereReference(const Atmosphere& atmosphere, const AtmosphereSun& sun,
                                         const AtmosphereReferenceSettings& settings)
    : atmosphere_(atmosphere), sun_(sun), settings_(settings) {
  sun_.direction = normalize(sun_.direction);
}

Vec3 AtmosphereReference::transmittance(double r, double mu) const {
  return physics::transmittance_to_boundary(atmosphere_, r, mu);
}

// J(x) = (σ_R P_R(ν) + σ_M P_M(ν)) E T_sun(x): the sun's light scattered once toward the
// viewer at x (Bruneton 2017, eq. 4's integrand without the view transmittance).
Vec3 AtmosphereReference::in_scattering(const Vec3& point, const Vec3& direction, const Vec3& sun) const {
  const double r = std::max(length_of(point), atmosphere_.bottom_radius);
  const double h = r - atmosphere_.bottom_radius;
  const double mu_s = std::clamp(dot(point, sun) / length_of(point), -1.0, 1.0);
  const Vec3 t_sun = physics::sun_transmittance(atmosphere_, std::min(r, atmosphere_.top_radius), mu_s);
  const double nu = std::clamp(dot(direction, sun), -1.0, 1.0);
  const Vec3 rayleigh = scaled(physics::rayleigh_scattering_at(atmosphere_, h), physics::phase_rayleigh(nu));
  const Vec3 mie = scaled(physics::mie_scattering_at(atmosphere_, h), physics::mie_phase(atmosphere_, nu));
  return times(times(add(rayleigh, mie), t_sun), sun_.irradiance);
}

// ∫₀^D T(0,t) J(t) dt by adaptive Simpson (Lyness 1969), T from physics' optical depth.
Vec3 AtmosphereReference::single_scattering_along(const Vec3& position, const Vec3& direction, double length,
                                                  const Vec3& sun) const {
  if (length <= 0) return {0, 0, 0};
  const double r = length_of(position), mu = std::clamp(dot(position, direction) / r, -1.0, 1.0);
  const auto f = [&](double t) {
    const Vec3 tau = physics::optical_depth(atmosphere_, r, mu, t);
    return times(exp_negative(tau), in_scattering(add(position, scaled(direction, t)), direction, sun));
  };
  const auto simpson = [](double a, double b, const Vec3& fa, const Vec3& fm, const Vec3& fb) {
    Vec3 s;
    for (int c = 0; c < 3; ++c) s[c] = (b - a) / 6 * (fa[c] + 4 * fm[c] + fb[c]);
    return s;
  };
  struct Panel {
    double a, b;
    Vec3 fa, fm, fb, whole;
    uint32_t depth;
  };
  const uint32_t n = std::max(1u, settings_.initial_panels);
  std::vector<Panel> panels;
  Vec3 estimate{0, 0, 0};
  Vec3 f_left = f(0);
  for (uint32_t i = 0; i < n; ++i) {
    const double a = length * i / n, b = length * (i + 1) / n;
    const Vec3 fm = f(0.5 * (a + b)), fb = f(b);
    const Vec3 whole = simpson(a, b, f_left, fm, fb);
    estimate = add(estimate, whole);
    panels.push_back({a, b, f_left, fm, fb, whole, 0});
    f_left = fb;
  }
  const double tolerance_per_metre = settings_.relative_tolerance * largest(estimate) / length;
  Vec3 sum{0, 0, 0};
  while (!panels.empty()) {
    const Panel p = panels.back();
    panels.pop_back();
    const double m = 0.5 * (p.a + p.b);
    const Vec3 fl = f(0.5 * (p.a + m)), fr = f(0.5 * (m + p.b));
    const Vec3 left = simpson(p.a, m, p.fa, fl, p.fm), right = simpson(m, p.b, p.fm, fr, p.fb);
    double error = 0;
    Vec3 refined;
    for (int c = 0; c < 3; ++c) {
      const double s2 = left[c] + right[c];
      error = std::max(error, std::abs(s2 - p.whole[c]) / 15);
      refined[c] = s2 + (s2 - p.whole[c]) / 15;  // Richardson
    }
    // A non-finite estimate is not refined (it would bisect to max_depth everywhere).
    if (!std::isfinite(error) || error <= tolerance_per_metre * (p.b - p.a) || p.depth >= settings_.max_depth) {
      sum = add(sum, refined);
      continue;
    }
    panels.push_back({p.a, m, p.fa, fl, p.fm, left, p.depth + 1});
    panels.push_back({m, p.b, p.fm, fr, p.fb, right, p.depth + 1});
  }
  for (double& c : sum) c = std::max(0.0, c);
  return sum;
}

Vec3 AtmosphereReference::single_scattering(double r, double mu, double mu_s, double nu) const {
  const double sin_v = std::sqrt(std::max(0.0, 1 - mu * mu));
  const Vec3 position{0, r, 0}, direction{sin_v, mu, 0};
  // The sun at zenith cosine mu_s and at cosine nu from the view (its x from s·v = nu).
  const double sx = sin_v > 1e-12 ? std::clamp((nu - mu * mu_s) / sin_v, -1.0, 1.0) : 0.0;
  const Vec3 sun{sx, mu_s, std::sqrt(std::max(0.0, 1 - mu_s * mu_s - sx * sx))};
  return single_scattering_along(position, direction, physics::distance_to_boundary(atmosphere_, r, mu),
                                 normalize(sun));
}

Vec3 AtmosphereReference::single_scattering(const Vec3& position, const Vec3& direction, double length) const {
  return single_scattering_along(position, direction, length, sun_.direction);
}

// The sun's light reflected once by the Lambertian ground toward the viewer:
// albedo/π · E · T_sun · max(μ_s, 0) (Bruneton 2017's ground radiance, its sun term).
Vec3 AtmosphereReference::ground_direct(const Vec3& ground_point) const {
  const double mu_s = std::clamp(dot(ground_point, sun_.direction) / length_of(ground_point), -1.0, 1.0);
  if (mu_s <= 0) return {0, 0, 0};
  const Vec3 t_sun = physics::sun_transmittance(atmosphere_, atmosphere_.bottom_radius, mu_s);
  return scaled(times(times(atmosphere_.ground_albedo, sun_.irradiance), t_sun), mu_s / kPi);
}

ScatteringOrders AtmosphereReference::scatter(const Vec3& position, const Vec3& direction, double length,
                                              bool ends_on_ground, uint64_t key) const {
  const Atmosphere& a = atmosphere_;
  const uint32_t max_orders = std::max(2u, settings_.max_orders);
  ScatteringOrders out;
  out.radiance.assign(max_orders, {0, 0, 0});
  out.standard_error.assign(max_orders, {0, 0, 0});
  const double r0 = length_of(position), mu0 = std::clamp(dot(position, direction) / r0, -1.0, 1.0);
  const Vec3 ground_point = add(position, scaled(direction, length));
  const Vec3 view_transmittance_to_end = exp_negative(physics::optical_depth(a, r0, mu0, length));

  // Order 1: deterministic.
  out.radiance[0] = single_scattering_along(position, direction, length, sun_.direction);
  if (ends_on_ground)
    out.radiance[0] = add(out.radiance[0], times(view_transmittance_to_end, ground_direct(ground_point)));

  // Orders ≥ 2: paths drawn by a hero channel chosen at random, each tallying every channel.
  const double g = a.mie_g;
  std::vector<Vec3> sum(max_orders, Vec3{0, 0, 0}), sum_sq(max_orders, Vec3{0, 0, 0});
  const uint32_t samples = settings_.samples;
  for (uint32_t s = 0; s < samples && length > 0; ++s) {
    Random random(splitmix64(splitmix64(splitmix64(settings_.seed) ^ key) ^ uint64_t(s)));
    const int hero = std::min(2, int(random.uniform() * 3));
    std::vector<Vec3> tally(max_orders, Vec3{0, 0, 0});

    // NEE toward the sun at an air vertex (the path's direction d arriving there: toward
    // the viewer is −d, the phase's cosine s·d): (σ_R P_R + σ_M P_M) E T_sun.
    const auto air_nee = [&](const Vec3& y, const Vec3& d) {
      const double h = altitude_of(a, y), r = std::clamp(length_of(y), a.bottom_radius, a.top_radius);
      const double mu_s = std::clamp(dot(y, sun_.direction) / length_of(y), -1.0, 1.0);
      const double cos_theta = std::clamp(dot(sun_.direction, d), -1.0, 1.0);
      const Vec3 sigma = add(scaled(physics::rayleigh_scattering_at(a, h), physics::phase_rayleigh(cos_theta)),
                             scaled(physics::mie_scattering_at(a, h), physics::mie_phase(a, cos_theta)));
      return times(times(sigma, sun_.irradiance), physics::sun_transmittance(a, r, mu_s));
    };
    // A new direction after scattering at y from direction d, by the hero's lobe mixture
    // (the lobe by σ_lobe/σ_s, Rayleigh's cosine exactly, Mie's from Henyey–Greenstein);
    // nullopt where the hero does not scatter.
    const auto scatter_direction = [&](const Vec3& y, const Vec3& d, Throughput& beta) -> std::optional<Vec3> {
      const double h = altitude_of(a, y);
      const Vec3 rayleigh = physics::rayleigh_scattering_at(a, h), mie = physics::mie_scattering_at(a, h);
      const double total_h = rayleigh[hero] + mie[hero];
      if (!(total_h > 0)) return std::nullopt;
      const double cos_theta = random.uniform() * total_h < rayleigh[hero] ? sample_rayleigh_cosine(random.uniform())
                                                                          : physics::sample_hg_cosine(g, random.uniform());
      const double p_rayleigh = physics::phase_rayleigh(cos_theta), p_mie = physics::mie_phase(a, cos_theta);
      const double q_mie = std::abs(g) < 1e-3 ? physics::phase_isotropic<double>() : physics::phase_hg(g, cos_theta);
      Vec3 f, p;
      for (int c = 0; c < 3; ++c) {
        f[c] = rayleigh[c] * p_rayleigh + mie[c] * p_mie;
        const double total = rayleigh[c] + mie[c];
        p[c] = total > 0 ? (rayleigh[c] * p_rayleigh + mie[c] * q_mie) / total : 0.0;
      }
      beta.step(f, p, hero);
      return physics::around(d, cos_theta, 2 * kPi * random.uniform());
    };
    // Cosine-weighted about the ground's normal (every strategy alike): throughput × albedo.
    const auto reflect = [&](const Vec3& y, Throughput& beta) {
      beta.f_over_hero = times(beta.f_over_hero, a.ground_albedo);
      const double xi = random.uniform();
      return physics::around(normalize(y), std::sqrt(xi), 2 * kPi * random.uniform());
    };
    const auto transmittance_along = [&](const Vec3& y, const Vec3& d, double t) {
      const double r = std::clamp(length_of(y), a.bottom_radius, a.top_radius);
      return exp_negative(physics::optical_depth(a, r, std::clamp(dot(y, d) / length_of(y), -1.0, 1.0), t));
    };
    // Continues a path from vertex `order` at y along d, tallying NEE at orders ≥ 2. Each
    // segment's next vertex is in the air (a forced collision, drawn by draw_distance) or,
    // where the segment ends on the ground, on the ground, chosen with probability
    // q = 1 − T̃ (clamped to [0.1, 0.9]) against 1 − q; Russian roulette (survival ≥ 0.05,
    // the largest channel's estimate over its value at vertex 1) ends the paths.
    const auto walk = [&](Vec3 y, Vec3 d, Throughput beta, uint32_t order) {
      const double first = largest(beta.estimate());
      while (order < max_orders && first > 0) {
        if (order >= 3) {
          const double survival = std::clamp(largest(beta.estimate()) / first, 0.05, 1.0);
          if (random.uniform() >= survival) return;
          beta.scale(1 / survival);
        }
        const RayEnd end = ray_end(a, y, d);
        if (!(end.length > 0)) return;
        const SegmentTable table = tabulate(a, y, d, end.length);
        Vec3 q{1, 1, 1};
        if (end.ground)
          for (int c = 0; c < 3; ++c) q[c] = std::clamp(-std::expm1(-table.tau.back()[c]), 0.1, 0.9);
        ++order;
        if (random.uniform() < q[hero]) {
          const double t = draw_distance(table, hero, random);
          Vec3 p;
          for (int j = 0; j < 3; ++j) p[j] = distance_density(table, j, t) * q[j];
          beta.step(transmittance_along(y, d, t), p, hero);
          y = add(y, scaled(d, t));
          tally[order - 1] = add(tally[order - 1], times(beta.estimate(), air_nee(y, d)));
          const std::optional<Vec3> next = scatter_direction(y, d, beta);
          if (!next) return;
          d = *next;
          continue;
        }
        beta.step(transmittance_along(y, d, end.length), {1 - q[0], 1 - q[1], 1 - q[2]}, hero);
        y = scaled(normalize(add(y, scaled(d, end.length))), a.bottom_radius);
        tally[order - 1] = add(tally[order - 1], times(beta.estimate(), ground_direct(y)));
        d = reflect(y, beta);
      }
    };

    // Vertex 1 in the air, drawn as the others, weighted by the exact transmittance.
    {
      const SegmentTable table = tabulate(a, position, direction, length);
      const double t = draw_distance(table, hero, random);
      Throughput beta;
      beta.step(exp_negative(physics::optical_depth(a, r0, mu0, t)),
                {distance_density(table, 0, t), distance_density(table, 1, t), distance_density(table, 2, t)}, hero);
      const Vec3 y = add(position, scaled(direction, t));
      tally[0] = add(tally[0], times(beta.estimate(), air_nee(y, direction)));  // the check of order 1
      if (const std::optional<Vec3> d = scatter_direction(y, direction, beta)) walk(y, *d, beta, 1);
    }
    // Vertex 1 on the ground, by its exact transmittance (every strategy alike).
    if (ends_on_ground) {
      Throughput beta;
      beta.f_over_hero = view_transmittance_to_end;
      const Vec3 y = scaled(normalize(ground_point), a.bottom_radius);
      tally[0] = add(tally[0], times(beta.estimate(), ground_direct(y)));
      const Vec3 d = reflect(y, beta);
      walk(y, d, beta, 1);
    }
    for (uint32_t k = 0; k < max_orders; ++k)
      for (int c = 0; c < 3; ++c) {
        sum[k][c] += tally[k][c];
        sum_sq[k][c] += tally[k][c] * tally[k][c];
      }
  }
  for (uint32_t k = 0; k < max_orders && samples > 0; ++k) {
    for (int c = 0; c < 3; ++c) {
      const double mean = sum[k][c] / samples;
      const double spread = std::max(0.0, sum_sq[k][c] / samples - mean * mean);
      const double variance = samples > 1 ? spread * samples / (samples - 1) : 0.0;
      (k == 0 ? out.order_one_estimate : out.radiance[k])[c] = mean;
      (k == 0 ? out.order_one_error : out.standard_error[k])[c] = std::sqrt(variance / samples);
    }
  }
  // N: the first order ≥ 2 after which the orders traced add at most order_threshold of
  // orders 1…N (largest channel).
  std::vector<Vec3> beyond(max_orders + 1, Vec3{0, 0, 0});  // beyond[k]: Σ orders k+1…
  for (uint32_t k = max_orders; k-- > 0;) beyond[k] = add(beyond[k + 1], out.radiance[k]);
  out.orders = max_orders;
  Vec3 running = out.radiance[0];
  for (uint32_t k = 1; k < max_orders; ++k) {
    running = add(running, out.radiance[k]);
    if (largest(beyond[k + 1]) <= settings_.order_threshold * largest(running)) {
      out.orders = k + 1;
      break;
    }
  }
  for (uint32_t k = 0; k < max_orders; ++k) {
    Vec3& part = k < out.orders ? out.total : out.residual;
    part = add(part, out.radiance[k]);
  }
  return out;
}

SkySample AtmosphereReference::sky(const Vec3& position, const Vec3& direction_in, uint64_t key) const {
  const Atmosphere& a = atmosphere_;
  const Vec3 direction = normalize(direction_in);
  SkySample out;
  Vec3 p = on_or_above_ground(a, position);
  double r = length_of(p);
  if (r > a.top_radius) {  // from space: enter at the top, or see the sun unattenuated
    const std::optional<double> entry = physics::enter_atmosphere(a, r, dot(p, direction) / r);
    if (!entry) {
      if (dot(direction, sun_.direction) >= std::cos(sun_.angular_radius)) out.sun_disk = sun_radiance(sun_);
      out.radiance = out.sun_disk;
      out.scattering = no_scattering();
      return out;
    }
    p = scaled(normalize(add(p, scaled(direction, *entry))), a.top_radius);
    r = a.top_radius;
  }
  const double mu = std::clamp(dot(p, direction) / r, -1.0, 1.0);
  out.hits_ground = physics::ray_hits_ground(a, r, mu);
  const double length = physics::distance_to_boundary(a, r, mu);
  out.transmittance = exp_negative(physics::optical_depth(a, r, mu, length));
  if (!out.hits_ground && dot(direction, sun_.direction) >= std::cos(sun_.angular_radius))
    out.sun_disk = times(sun_radiance(sun_), out.transmittance);
  out.scattering = scatter(p, direction, length, out.hits_ground, key);
  out.radiance = add(out.scattering.total, out.sun_disk);
  return out;
}

AerialPerspectiveSample AtmosphereReference::aerial_perspective(const Vec3& position, const Vec3& direction_in,
                                                                double distance, uint64_t key) const {
  const Atmosphere& a = atmosphere_;
  const Vec3 direction = normalize(direction_in);
  AerialPerspectiveSample out;
  Vec3 p = on_or_above_ground(a, position);
  double r = length_of(p), d = distance;
  if (r > a.top_radius) {
    const std::optional<double> entry = physics::enter_atmosphere(a, r, dot(p, direction) / r);
    if (!entry || *entry >= distance) {
      out.scattering = no_scattering();
      return out;
    }
    p = scaled(normalize(add(p, scaled(direction, *entry))), a.top_radius);
    r = a.top_radius;
    d -= *entry;
  }
  const double mu = std::clamp(dot(p, direction) / r, -1.0, 1.0);
  d = std::min(d, physics::distance_to_boundary(a, r, mu));
  out.transmittance = exp_negative(physics::optical_depth(a, r, mu, d));
  out.scattering = scatter(p, direction, d, false, key);
  out.in_scattered = out.scattering.total;
  return out;
}

Vec3 AtmosphereReference::air_in_scattering(const Vec3& point, const Vec3& direction) const {
  return in_scattering(point, normalize(direction), sun_.direction);
}

Vec3 AtmosphereReference::transmittance_along(const Vec3& position, const Vec3& direction_in, double distance) const {
  const Atmosphere& a = atmosphere_;
  const Vec3 direction = normalize(direction_in);
  Vec3 p = on_or_above_ground(a, position);
  double r = length_of(p), d = distance;
  if (r > a.top_radius) {
    const std::optional<double> entry = physics::enter_atmosphere(a, r, dot(p, direction) / r);
    if (!entry || *entry >= distance) return {1, 1, 1};
    p = scaled(normalize(add(p, scaled(direction, *entry))), a.top_radius);
    r = a.top_radius;
    d -= *entry;
  }
  const double mu = std::clamp(dot(p, direction) / r, -1.0, 1.0);
  return exp_negative(physics::optical_depth(a, r, mu, std::min(d, physics::distance_to_boundary(a, r, mu))));
}

SkyImage render_sky_image(const AtmosphereReference& reference, const Camera& camera, const RenderSettings& settings) {
  const Vec3 eye = planet_position(reference.atmosphere(), camera.position);
  std::vector<uint32_t> orders(size_t(settings.width) * settings.height, 0);
  std::vector<double> residuals(orders.size(), 0.0), errors(orders.size(), 0.0);
  SkyImage out;
  out.image = render_pixels(
      [&](uint32_t i, uint32_t j) {
        const uint64_t key = uint64_t(j) * settings.width + i;
        const SkySample s = reference.sky(eye, physics::pixel_ray(camera, settings.width, settings.height, i, j), key);
        orders[key] = s.scattering.orders;
        const double total = largest(s.scattering.total);
        residuals[key] = total > 0 ? largest(s.scattering.residual) / total : 0.0;
        for (int c = 0; c < 3; ++c) {
          double variance = 0;
          for (uint32_t k = 1; k < s.scattering.orders; ++k) variance += std::pow(s.scattering.standard_error[k][c], 2);
          const double t = s.scattering.total[c];
          if (t > 0) errors[key] = std::max(errors[key], std::sqrt(variance) / t);
        }
        return s.radiance;
      },
      settings);
  out.max_orders = *std::max_element(orders.begin(), orders.end());
  out.max_relative_residual = *std::max_element(residuals.begin(), residuals.end());
  out.max_relative_standard_error = *std::max_element(errors.begin(), errors.end());
  for (double e : errors) out.mean_relative_standard_error += e / double(errors.size());
  return out;
}

}  // namespace volgraph::reference
