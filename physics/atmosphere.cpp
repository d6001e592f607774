// A planet's atmosphere (Bruneton 2017's model): see atmosphere.h.
#include "physics/atmosphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "physics/phase.h"
#include "physics/vec3.h"

namespace volgraph::physics {
namespace {


// The layer of `profile` that holds altitude h (Bruneton 2017, GetProfileDensity).
const DensityLayer& layer_at(const DensityProfile& profile, double altitude) {
  return altitude < profile.lower.width ? profile.lower : profile.upper;
}

// A layer's density before the clamp to [0, 1].
double unclamped_density(const DensityLayer& layer, double altitude) {
  return layer.exp_term * std::exp(layer.exp_scale * altitude) + layer.linear_term * altitude + layer.constant_term;
}

// ∫ unclamped density dh over [a, b], exactly: exponential and linear terms
// (the exponential's written with expm1 so it keeps its precision as exp_scale → 0).
double unclamped_integral(const DensityLayer& layer, double a, double b) {
  const double width = b - a;
  double exponential = layer.exp_term * width;
  if (layer.exp_scale != 0) exponential = layer.exp_term * std::exp(layer.exp_scale * a) * std::expm1(layer.exp_scale * width) / layer.exp_scale;
  return exponential + layer.linear_term * 0.5 * (b * b - a * a) + layer.constant_term * width;
}

// A root of f(h) = level in [a, b] where f − level changes sign (bisection; f monotonic there).
double bisect_level(const DensityLayer& layer, double level, double a, double b) {
  const bool rising = unclamped_density(layer, b) > unclamped_density(layer, a);
  for (int i = 0; i < 100 && b - a > 1e-9 * std::max(1.0, std::abs(a)); ++i) {
    const double mid = 0.5 * (a + b);
    if ((unclamped_density(layer, mid) < level) == rising) a = mid; else b = mid;
  }
  return 0.5 * (a + b);
}

// Where a layer's unclamped density crosses 0 or 1 inside (a, b): exp + linear is convex
// or concave, so split at its extremum (f' = 0) and bisect each monotonic piece.
void add_clamp_crossings(const DensityLayer& layer, double a, double b, std::vector<double>& out) {
  std::vector<double> pieces{a};
  if (layer.exp_term != 0 && layer.exp_scale != 0 && layer.linear_term != 0) {
    const double ratio = -layer.linear_term / (layer.exp_term * layer.exp_scale);
    if (ratio > 0) {
      const double extremum = std::log(ratio) / layer.exp_scale;
      if (extremum > a && extremum < b) pieces.push_back(extremum);
    }
  }
  pieces.push_back(b);
  for (size_t i = 0; i + 1 < pieces.size(); ++i) {
    for (double level : {0.0, 1.0}) {
      const double fa = unclamped_density(layer, pieces[i]) - level, fb = unclamped_density(layer, pieces[i + 1]) - level;
      if (fa * fb < 0) out.push_back(bisect_level(layer, level, pieces[i], pieces[i + 1]));
    }
  }
}

// The altitudes in (0, top) where a profile's density has a kink: the layer boundary and
// where a layer clamps at 0 or 1.
void add_profile_kinks(const DensityProfile& profile, double top, std::vector<double>& out) {
  const double boundary = std::clamp(profile.lower.width, 0.0, top);
  if (boundary > 0 && boundary < top) out.push_back(boundary);
  if (boundary > 0) add_clamp_crossings(profile.lower, 0, boundary, out);
  add_clamp_crossings(profile.upper, boundary, top, out);
}

// An exponential term below e^(−80) ≈ 1.8e-35 is negligible: over the rest of the ray it
// adds at most that times its scale height, far below a double's precision on any density
// that is not itself negligible (docs/reference.md, thin air).
constexpr double kNegligibleExponential = 1.8e-35;

// Whether a layer's exponential term matters at altitude h (a growing one always does).
bool exponential_matters(const DensityLayer& layer, double altitude) {
  if (layer.exp_term == 0 || layer.exp_scale == 0) return false;
  return layer.exp_scale > 0 || std::abs(layer.exp_term) * std::exp(layer.exp_scale * altitude) > kNegligibleExponential;
}

// Where a decaying exponential term falls to the negligible level, inside [from, to):
// above it the panels need not resolve its scale height.
void add_negligible_altitude(const DensityLayer& layer, double from, double to, std::vector<double>& out) {
  if (layer.exp_term == 0 || !(layer.exp_scale < 0)) return;
  const double altitude = std::log(kNegligibleExponential / std::abs(layer.exp_term)) / layer.exp_scale;
  if (altitude > from && altitude < to) out.push_back(altitude);
}

void add_negligible_altitudes(const DensityProfile& profile, double top, std::vector<double>& out) {
  const double boundary = std::clamp(profile.lower.width, 0.0, top);
  if (boundary > 0) add_negligible_altitude(profile.lower, 0, boundary, out);
  add_negligible_altitude(profile.upper, boundary, top, out);
}

// The kinks, and the altitudes above which a layer's exponential is negligible.
std::vector<double> kink_altitudes(const Atmosphere& atmosphere) {
  const double top = atmosphere.top_radius - atmosphere.bottom_radius;
  std::vector<double> kinks;
  for (const DensityProfile* p : {&atmosphere.rayleigh_density, &atmosphere.mie_density, &atmosphere.absorption_density}) {
    add_profile_kinks(*p, top, kinks);
    add_negligible_altitudes(*p, top, kinks);
  }
  return kinks;
}

// The smallest scale height 1/|exp_scale| among the layers whose exponential term matters at
// altitude h (the atmosphere's thickness when there is none; at least 1 mm, the loader's floor).
// A ray's segment between breaks lies wholly on one side of each negligible altitude, so
// the segment's midpoint decides for all of it.
double smallest_scale_height_at(const Atmosphere& atmosphere, double altitude) {
  double smallest = atmosphere.top_radius - atmosphere.bottom_radius;
  for (const DensityProfile* p : {&atmosphere.rayleigh_density, &atmosphere.mie_density, &atmosphere.absorption_density}) {
    const DensityLayer& layer = layer_at(*p, altitude);
    if (exponential_matters(layer, altitude)) smallest = std::min(smallest, 1.0 / std::abs(layer.exp_scale));
  }
  return std::max(smallest, 1e-3);
}

// 8-point Gauss–Legendre nodes and weights on [−1, 1] (Abramowitz & Stegun, Table 25.4).
constexpr std::array<double, 4> kGaussNodes{0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kGaussWeights{0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

// The altitude from altitude_at, not r_d − bottom: at planet scale the difference keeps only
// ~1e-9 m, 1e-6 of a 1 mm scale height.
Vec3 extinction_along(const Atmosphere& atmosphere, double r, double mu, double d) {
  return extinction_at(atmosphere, altitude_at(atmosphere, r, mu, d));
}

// ∫ extinction over [d0, d1] of the ray in `panels` equal 8-point Gauss–Legendre panels.
Vec3 gauss_legendre(const Atmosphere& atmosphere, double r, double mu, double d0, double d1, int panels) {
  Vec3 total{0, 0, 0};
  const double width = (d1 - d0) / panels;
  for (int p = 0; p < panels; ++p) {
    const double centre = d0 + (p + 0.5) * width, half = 0.5 * width;
    for (size_t i = 0; i < kGaussNodes.size(); ++i) {
      const Vec3 sides = add(extinction_along(atmosphere, r, mu, centre - half * kGaussNodes[i]),
                             extinction_along(atmosphere, r, mu, centre + half * kGaussNodes[i]));
      total = add(total, scaled(sides, kGaussWeights[i] * half));
    }
  }
  return total;
}

// The distances in (0, length) where the ray crosses a sphere at one of the kink
// altitudes, and its lowest point (d = −r·mu): between them the density is smooth and the
// altitude monotonic.
std::vector<double> ray_breaks(const Atmosphere& atmosphere, double r, double mu, double length) {
  std::vector<double> breaks{0.0, length};
  const double b = r * mu;
  if (-b > 0 && -b < length) breaks.push_back(-b);
  for (double kink : kink_altitudes(atmosphere)) {
    const double c = sphere_constant_term(r, atmosphere.bottom_radius + kink);
    if (b * b - c < 0) continue;
    for (double d : {sphere_near_root(b, c), sphere_far_root(b, c)})
      if (d > 0 && d < length) breaks.push_back(d);
  }
  std::sort(breaks.begin(), breaks.end());
  return breaks;
}

}  // namespace

double layer_density(const DensityLayer& layer, double altitude) {
  return std::clamp(unclamped_density(layer, altitude), 0.0, 1.0);
}

double profile_density(const DensityProfile& profile, double altitude) {
  return layer_density(layer_at(profile, altitude), altitude);
}

// Bruneton 2017, ComputeOpticalLengthToTopAtmosphereBoundary's integrand: coefficient × density.
Vec3 rayleigh_scattering_at(const Atmosphere& atmosphere, double altitude) {
  return scaled(atmosphere.rayleigh_scattering, profile_density(atmosphere.rayleigh_density, altitude));
}

Vec3 mie_scattering_at(const Atmosphere& atmosphere, double altitude) {
  return scaled(atmosphere.mie_scattering, profile_density(atmosphere.mie_density, altitude));
}

Vec3 mie_extinction_at(const Atmosphere& atmosphere, double altitude) {
  return scaled(atmosphere.mie_extinction, profile_density(atmosphere.mie_density, altitude));
}

Vec3 absorption_at(const Atmosphere& atmosphere, double altitude) {
  return scaled(atmosphere.absorption_extinction, profile_density(atmosphere.absorption_density, altitude));
}

// Bruneton 2017, ComputeTransmittanceToTopAtmosphereBoundary: Rayleigh + Mie extinction + absorption.
Vec3 extinction_at(const Atmosphere& atmosphere, double altitude) {
  return add(add(rayleigh_scattering_at(atmosphere, altitude), mie_extinction_at(atmosphere, altitude)), absorption_at(atmosphere, altitude));
}

double distance_to_top(const Atmosphere& atmosphere, double r, double mu) {
  const double c = sphere_constant_term(r, atmosphere.top_radius);
  return std::max(sphere_far_root(r * mu, c), 0.0);
}

bool ray_hits_ground(const Atmosphere& atmosphere, double r, double mu) {
  const double b = r * mu, c = sphere_constant_term(r, atmosphere.bottom_radius);
  return mu < 0 && b * b - c >= 0;
}

std::optional<double> distance_to_ground(const Atmosphere& atmosphere, double r, double mu) {
  if (!ray_hits_ground(atmosphere, r, mu)) return std::nullopt;
  return std::max(sphere_near_root(r * mu, sphere_constant_term(r, atmosphere.bottom_radius)), 0.0);
}

double distance_to_boundary(const Atmosphere& atmosphere, double r, double mu) {
  return distance_to_ground(atmosphere, r, mu).value_or(distance_to_top(atmosphere, r, mu));
}

std::optional<double> enter_atmosphere(const Atmosphere& atmosphere, double r, double mu) {
  if (r <= atmosphere.top_radius) return 0.0;
  return distance_to_sphere(r, mu, atmosphere.top_radius);
}

// Law of cosines: r_d² = r² + d(d + 2r·mu); r_d − r = d(d + 2r·mu) / (r + r_d).
double radius_at(double r, double mu, double d) {
  const double growth = d * (d + 2 * r * mu);
  const double r_d = std::sqrt(std::max(r * r + growth, 0.0));
  if (r + r_d <= 0) return 0;
  return std::max(r + growth / (r + r_d), 0.0);
}

// Bruneton 2017, ComputeSingleScatteringIntegrand: mu_d = (r·mu + d) / r_d.
double mu_at(double r, double mu, double d) {
  const double r_d = radius_at(r, mu, d);
  if (r_d <= 0) return mu;
  return std::clamp((r * mu + d) / r_d, -1.0, 1.0);
}

double mu_s_at(double r, double mu, double mu_s, double nu, double d) {
  const double rd = radius_at(r, mu, d);
  return rd > 0 ? std::clamp((r * mu_s + d * nu) / rd, -1.0, 1.0) : mu_s;
}

double altitude_at(const Atmosphere& atmosphere, double r, double mu, double d) {
  const double growth = d * (d + 2 * r * mu);
  const double r_d = std::sqrt(std::max(r * r + growth, 0.0));
  if (r + r_d <= 0) return -atmosphere.bottom_radius;
  return (r - atmosphere.bottom_radius) + growth / (r + r_d);
}

// 4-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun, Table 25.4), as atmosphere.glsl.
constexpr std::array<double, 2> kGauss4Nodes{0.3399810435848563, 0.8611363115940526};
constexpr std::array<double, 2> kGauss4Weights{0.6521451548625461, 0.3478548451374538};

Vec3 optical_depth_fixed(const Atmosphere& atmosphere, double r, double mu, double length, int panels) {
  Vec3 total{0, 0, 0};
  if (!(length > 0) || panels < 1) return total;
  const double half = 0.5 * length / panels;
  for (int p = 0; p < panels; ++p) {
    const double centre = (2 * p + 1) * half;
    for (size_t i = 0; i < kGauss4Nodes.size(); ++i) {
      const Vec3 sides = add(extinction_at(atmosphere, altitude_at(atmosphere, r, mu, centre - half * kGauss4Nodes[i])),
                             extinction_at(atmosphere, altitude_at(atmosphere, r, mu, centre + half * kGauss4Nodes[i])));
      total = add(total, scaled(sides, kGauss4Weights[i] * half));
    }
  }
  return total;
}

Vec3 optical_depth(const Atmosphere& atmosphere, double r, double mu, double length) {
  Vec3 total{0, 0, 0};
  if (!(length > 0)) return total;
  const std::vector<double> breaks = ray_breaks(atmosphere, r, mu, length);
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double d0 = breaks[i], d1 = breaks[i + 1];
    if (d1 <= d0) continue;
    const double scale_height = smallest_scale_height_at(atmosphere, altitude_at(atmosphere, r, mu, 0.5 * (d0 + d1)));
    const double altitude_span = std::abs(radius_at(r, mu, d1) - radius_at(r, mu, d0));
    const int panels = int(std::clamp(std::ceil(altitude_span / (2 * scale_height)), 1.0, 4096.0));
    total = add(total, gauss_legendre(atmosphere, r, mu, d0, d1, panels));
  }
  return total;
}

Vec3 optical_depth_to_boundary(const Atmosphere& atmosphere, double r, double mu) {
  return optical_depth(atmosphere, r, mu, distance_to_boundary(atmosphere, r, mu));
}

double profile_integral(const DensityProfile& profile, double from, double to) {
  if (!(to > from)) return 0;
  std::vector<double> cuts{from, to};
  add_profile_kinks(profile, to, cuts);
  std::sort(cuts.begin(), cuts.end());
  double total = 0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = std::max(cuts[i], from), b = cuts[i + 1];
    if (b <= a) continue;
    const DensityLayer& layer = layer_at(profile, 0.5 * (a + b));
    // Between kinks the density is wholly ≤ 0, in (0, 1) or ≥ 1; the sign is read from the
    // integral, not the midpoint, whose exponential underflows to 0 in thin air (H = 1 mm).
    if (unclamped_density(layer, 0.5 * (a + b)) >= 1) total += b - a;
    else total += std::max(unclamped_integral(layer, a, b), 0.0);
  }
  return total;
}

// ∫ extinction from h to the top: each coefficient times its profile's exact integral.
Vec3 zenith_optical_depth(const Atmosphere& atmosphere, double altitude) {
  const double top = atmosphere.top_radius - atmosphere.bottom_radius;
  const Vec3 rayleigh = scaled(atmosphere.rayleigh_scattering, profile_integral(atmosphere.rayleigh_density, altitude, top));
  const Vec3 mie = scaled(atmosphere.mie_extinction, profile_integral(atmosphere.mie_density, altitude, top));
  const Vec3 ozone = scaled(atmosphere.absorption_extinction, profile_integral(atmosphere.absorption_density, altitude, top));
  return add(add(rayleigh, mie), ozone);
}

Vec3 transmittance_to_boundary(const Atmosphere& atmosphere, double r, double mu) {
  return exp_negative(optical_depth_to_boundary(atmosphere, r, mu));
}

// Below the horizon Bruneton 2017's texture has no row (its lookup clamps to the horizon's):
// the same here, so the ray never passes through the planet.
Vec3 transmittance_to_top(const Atmosphere& atmosphere, double r, double mu) {
  mu = std::max(mu, mu_horizon(atmosphere, r));
  return exp_negative(optical_depth(atmosphere, r, mu, distance_to_top(atmosphere, r, mu)));
}

// −√(1 − (R/r)²) = −√(h(2R + h)) / r, from the altitude h = r − R.
double mu_horizon(const Atmosphere& atmosphere, double r) {
  if (r <= 0) return 0;
  return -std::sqrt(std::max(sphere_constant_term(r, atmosphere.bottom_radius), 0.0)) / r;
}

// Bruneton 2017, GetTransmittanceToSun: smoothstep(−sin θ_h·α, sin θ_h·α, mu_s − cos θ_h).
double sun_visible_fraction(const Atmosphere& atmosphere, double r, double mu_s) {
  const double sin_theta_h = std::min(atmosphere.bottom_radius / std::max(r, atmosphere.bottom_radius), 1.0);
  const double half_width = sin_theta_h * atmosphere.sun_angular_radius;
  const double x = mu_s - mu_horizon(atmosphere, r);
  if (half_width <= 0) return x >= 0 ? 1.0 : 0.0;
  const double t = std::clamp((x + half_width) / (2 * half_width), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

Vec3 sun_transmittance(const Atmosphere& atmosphere, double r, double mu_s) {
  const double fraction = sun_visible_fraction(atmosphere, r, mu_s);
  if (fraction <= 0) return {0, 0, 0};
  return scaled(transmittance_to_top(atmosphere, r, mu_s), fraction);
}

double mie_phase(const Atmosphere& atmosphere, double cos_theta) {
  if (atmosphere.mie_phase == MiePhase::henyey_greenstein) return phase_hg(atmosphere.mie_g, cos_theta);
  return phase_cornette_shanks(atmosphere.mie_g, cos_theta);
}

namespace {

// Mars. No published preset with every constant was found; the values are derived:
// - radius 3389.5 km (IAU mean radius), the air to 80 km (OpenSpace's Mars asset uses ~77 km);
// - Rayleigh of CO₂: Bruneton 2017's earth coefficients × the number density ratio
//   (610 Pa at 210 K vs 101325 Pa at 288 K: 0.0083) × CO₂'s cross-section over air's (≈ 2.4,
//   Sneep & Ubachs 2005), scale height 11.1 km (Mars' ≈ 11 km);
// - dust (Mie): extinction = optical depth 0.5 (a typical clear-season dust τ) / 11.1 km,
//   single-scattering albedo 0.97 red, 0.93 green, 0.85 blue (dust absorbs blue), g 0.65;
// - no ozone; ground albedo 0.25 (Mars' Bond albedo); the sun's angular radius
//   0.004675 rad / 1.524 AU.
Atmosphere mars_preset() {
  constexpr double kMarsOverEarthRayleigh = 0.0083 * 2.4;
  constexpr double kScaleHeight = 11.1e3;
  constexpr double kDustExtinction = 0.5 / kScaleHeight;
  Atmosphere mars;
  mars.preset = "mars";
  mars.bottom_radius = 3389.5e3;
  mars.top_radius = 3389.5e3 + 80e3;
  mars.rayleigh_scattering = scaled(Atmosphere{}.rayleigh_scattering, kMarsOverEarthRayleigh);
  mars.rayleigh_density = {{}, {0, 1, -1.0 / kScaleHeight, 0, 0}};
  mars.mie_extinction = {kDustExtinction, kDustExtinction, kDustExtinction};
  mars.mie_scattering = {0.97 * kDustExtinction, 0.93 * kDustExtinction, 0.85 * kDustExtinction};
  mars.mie_density = {{}, {0, 1, -1.0 / kScaleHeight, 0, 0}};
  mars.mie_g = 0.65;
  mars.absorption_extinction = {0, 0, 0};
  mars.absorption_density = {};
  mars.ground_albedo = {0.25, 0.25, 0.25};
  mars.sun_angular_radius = 0.004675 / 1.524;
  return mars;
}

}  // namespace

// earth: Bruneton 2017's demo (demo/demo.cc) constants, which Hillaire 2020 uses: the
// defaults of graph/scene/scene.h's Atmosphere.
std::optional<Atmosphere> atmosphere_preset(const std::string& name) {
  if (name == "earth") return Atmosphere{};
  if (name == "mars") return mars_preset();
  return std::nullopt;
}

namespace {

void pack_vec3(const Vec3& v, gpu::vec4& out, float w = 0) {
  for (int i = 0; i < 3; ++i) out[i] = float(v[size_t(i)]);
  out[3] = w;
}

gpu::AtmosphereLayer pack_layer(const DensityLayer& layer) {
  return {{float(layer.exp_term), float(layer.exp_scale), float(layer.linear_term), float(layer.constant_term)}};
}

gpu::AtmosphereProfile pack_profile(const DensityProfile& profile) {
  return {pack_layer(profile.lower), pack_layer(profile.upper), {float(profile.lower.width), 0, 0, 0}};
}

}  // namespace

GpuAtmosphere pack_atmosphere(const Atmosphere& atmosphere) {
  GpuAtmosphere out{};
  out.radii[0] = float(atmosphere.bottom_radius);
  out.radii[1] = float(atmosphere.top_radius);
  out.radii[2] = float(atmosphere.sun_angular_radius);
  out.radii[3] = float(atmosphere.mie_g);
  const float phase = atmosphere.mie_phase == MiePhase::henyey_greenstein ? kMiePhaseHenyeyGreenstein : kMiePhaseCornetteShanks;
  pack_vec3(atmosphere.rayleigh_scattering, out.rayleigh_scattering);
  pack_vec3(atmosphere.mie_scattering, out.mie_scattering, phase);
  pack_vec3(atmosphere.mie_extinction, out.mie_extinction);
  pack_vec3(atmosphere.absorption_extinction, out.absorption_extinction);
  pack_vec3(atmosphere.ground_albedo, out.ground_albedo);
  out.rayleigh_density = pack_profile(atmosphere.rayleigh_density);
  out.mie_density = pack_profile(atmosphere.mie_density);
  out.absorption_density = pack_profile(atmosphere.absorption_density);
  return out;
}

}  // namespace volgraph::physics
