#include "reference/clouds.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <thread>
#include <type_traits>

#include "passes/clouds/cloud_weather_map.h"
#include "physics/atmosphere_lighting.h"
#include "physics/cloud_density.h"
#include "physics/cloud_lighting.h"
#include "physics/cloud_noise.h"
#include "physics/cloud_phase_table.h"
#include "physics/vec3.h"

namespace volgraph::reference {
namespace {

using physics::add;
using physics::dot;
using physics::scaled;
using physics::sub;

namespace noise = physics::cloud_noise;
namespace density_fn = physics::cloud_density;
namespace lighting = physics::cloud_lighting;

constexpr double kEarthRadius = 6360e3;  // m: cloud_march's planet without an atmosphere

std::array<float, 4> to_array(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }

// Runs fill(z) for every slice z in [0, depth) on the machine's threads: the textures are
// a few million texels of Worley noise.
void for_slices(int depth, const std::function<void(int)>& fill) {
  const int workers = std::max(1, std::min(int(std::thread::hardware_concurrency()), depth));
  std::vector<std::thread> threads;
  for (int k = 0; k < workers; ++k) {
    threads.emplace_back([&, k] {
      for (int z = k; z < depth; z += workers) fill(z);
    });
  }
  for (std::thread& t : threads) t.join();
}

// The wrapped lower texel and the weight of the upper one, for normalised u on n texels
// (the linear filter: texel centres at (i + 0.5) / n).
void filter_axis(double u, int n, int& i0, int& i1, float& w) {
  const double x = u * n - 0.5;
  const double base = std::floor(x);
  w = float(x - base);
  const long long i = (long long)base;
  i0 = int(((i % n) + n) % n);
  i1 = (i0 + 1) % n;
}

// The ray o + t·d against the sphere of radius r centred at c: roots t0 ≤ t1, false if none.
bool sphere_roots(const Vec3& o, const Vec3& d, const Vec3& c, double r, double& t0, double& t1) {
  const Vec3 oc = sub(o, c);
  const double b = dot(oc, d);
  const double cc = dot(oc, oc) - r * r;
  const double disc = b * b - cc;
  if (disc < 0) return false;
  const double q = -(b + (b >= 0 ? 1.0 : -1.0) * std::sqrt(disc));
  const double ra = q, rb = q != 0 ? cc / q : 0;
  t0 = std::min(ra, rb);
  t1 = std::max(ra, rb);
  return true;
}

// Parameter `name` of graph pass `pass` as T, if the pass declares it and has values.
template <typename T>
void read_param(const GraphPass& pass, const std::vector<ParamValue>& values, const char* name, T& to) {
  const int k = pass.decl->param_index(name);
  if (k < 0 || size_t(k) >= values.size()) return;
  if (const auto* v = std::get_if<T>(&values[size_t(k)])) {
    to = *v;
  } else if constexpr (std::is_same_v<T, int64_t>) {  // an integer the loader kept as a number
    if (const auto* d = std::get_if<double>(&values[size_t(k)])) to = int64_t(*d);
  }
}

// The table of the cloud_phase_table pass whose output `pass` reads in its phase_table slot
// (its variant, size and droplets or g; the pass's defaults where the graph has none), or none.
std::optional<physics::CloudPhaseTable> wired_phase_table(const Graph& graph, const GraphPass& pass,
                                                          const std::vector<std::vector<ParamValue>>& params) {
  for (const ResourceUse& use : pass.uses) {
    if (use.direction != SlotDirection::input || pass.decl->slots[use.slot].name != "phase_table" || use.resource >= graph.resources.size())
      continue;
    const uint32_t creator = graph.resources[use.resource].creator;
    if (creator >= graph.passes.size() || !graph.passes[creator].decl || graph.passes[creator].decl->name != "cloud_phase_table") continue;
    const GraphPass& table = graph.passes[creator];
    static const std::vector<ParamValue> none;
    const std::vector<ParamValue>& v = !table.params.empty() ? table.params : (creator < params.size() ? params[creator] : none);
    int64_t size = 512;
    double g = 0.8;
    physics::DropletDistribution droplets;
    read_param(table, v, "size", size), read_param(table, v, "effective_radius", droplets.effective_radius_um);
    read_param(table, v, "effective_variance", droplets.effective_variance), read_param(table, v, "g", g);
    if (table.decl->variants[table.variant].name == "henyey_greenstein") return physics::henyey_greenstein_phase_table(g, uint32_t(size));
    return physics::cloud_droplet_phase_table(droplets, uint32_t(size));
  }
  return std::nullopt;
}

}  // namespace

CloudReferenceSettings cloud_reference_settings(const Graph& graph, const std::vector<std::vector<ParamValue>>& params,
                                                CloudReferenceSettings k) {
  bool noise = false, march = false, weather = false;
  for (size_t i = 0; i < graph.passes.size(); ++i) {
    const GraphPass& pass = graph.passes[i];
    if (!pass.decl) continue;
    // The graph pass's own values where it holds them, else the loader's per-pass list.
    static const std::vector<ParamValue> none;
    const std::vector<ParamValue>& v = !pass.params.empty() ? pass.params : (i < params.size() ? params[i] : none);
    if (!noise && pass.decl->name == "cloud_noise") {
      noise = true;
      int64_t shape = k.shape_size, detail = k.detail_size, curl = k.curl_size, seed = k.seed;
      read_param(pass, v, "shape_size", shape), read_param(pass, v, "detail_size", detail), read_param(pass, v, "curl_size", curl);
      read_param(pass, v, "seed", seed);
      k.shape_size = int(shape), k.detail_size = int(detail), k.curl_size = int(curl), k.seed = uint32_t(seed);
    } else if (!march && pass.decl->name == "cloud_march") {
      march = true;
      int64_t octaves = k.octaves;
      read_param(pass, v, "octaves", octaves);
      k.octaves = int(octaves);
      read_param(pass, v, "light_distance", k.light_distance), read_param(pass, v, "max_distance", k.max_distance);
      read_param(pass, v, "curl_strength", k.curl_strength), read_param(pass, v, "a", k.a), read_param(pass, v, "b", k.b);
      read_param(pass, v, "c", k.c), read_param(pass, v, "g_forward", k.g_forward), read_param(pass, v, "g_back", k.g_back);
      read_param(pass, v, "back_weight", k.back_weight), read_param(pass, v, "ambient", k.ambient);
      k.phase_table = wired_phase_table(graph, pass, params);
    } else if (!weather && pass.decl->name == "cloud_weather_map") {
      weather = true;
      int64_t size = k.weather_size;
      read_param(pass, v, "size", size);
      k.weather_size = int(size);
    }
  }
  return k;
}

float quantise_unorm8(float v) { return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f; }

void CloudTexture::store(int x, int y, int z, const std::array<float, 4>& v) {
  std::array<float, 4>& t = texels_[index(x, y, z)];
  for (size_t c = 0; c < 4; ++c) t[c] = quantise_unorm8(v[c]);
}

std::array<float, 4> CloudTexture::sample(double u, double v, double w) const {
  int x0, x1, y0, y1, z0 = 0, z1 = 0;
  float fx, fy, fz = 0;
  filter_axis(u, w_, x0, x1, fx);
  filter_axis(v, h_, y0, y1, fy);
  if (d_ > 1) filter_axis(w, d_, z0, z1, fz);
  std::array<float, 4> out{0, 0, 0, 0};
  for (int k = 0; k < 8; ++k) {
    const float weight = ((k & 1) ? fx : 1 - fx) * ((k & 2) ? fy : 1 - fy) * ((k & 4) ? fz : 1 - fz);
    if (weight == 0) continue;
    const std::array<float, 4>& t = texel((k & 1) ? x1 : x0, (k & 2) ? y1 : y0, (k & 4) ? z1 : z0);
    for (size_t c = 0; c < 4; ++c) out[c] += weight * t[c];
  }
  return out;
}

CloudTexture cloud_shape_texture(int size, uint32_t seed) {
  CloudTexture t(size, size, size);
  for_slices(size, [&](int z) {
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        t.store(x, y, z, to_array(noise::cloud_shape_texel((glm::vec3(float(x), float(y), float(z)) + 0.5f) / glm::vec3(float(size)), seed)));
  });
  return t;
}

CloudTexture cloud_detail_texture(int size, uint32_t seed) {
  CloudTexture t(size, size, size);
  for_slices(size, [&](int z) {
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x)
        t.store(x, y, z, to_array(noise::cloud_detail_texel((glm::vec3(float(x), float(y), float(z)) + 0.5f) / glm::vec3(float(size)), seed)));
  });
  return t;
}

CloudTexture cloud_curl_texture(int size, uint32_t seed) {
  CloudTexture t(size, size, 1);
  for_slices(size, [&](int y) {
    for (int x = 0; x < size; ++x)
      t.store(x, y, 0, to_array(noise::cloud_curl_texel((glm::vec2(float(x), float(y)) + 0.5f) / glm::vec2(float(size)), 1.0f / float(size), seed)));
  });
  return t;
}

// cloud_weather_map's texture of the map: the same texels, the same rgba8 storage.
CloudTexture cloud_weather_texture(const CloudWeatherMap& map, int size) {
  const std::vector<uint8_t> texels = clouds::weather_texels(plumbing::read_image_file(map.image), uint32_t(size));
  CloudTexture t(size, size, 1);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const uint8_t* b = &texels[(size_t(y) * size_t(size) + size_t(x)) * 4];
      t.store(x, y, 0, {b[0] / 255.0f, b[1] / 255.0f, b[2] / 255.0f, b[3] / 255.0f});
    }
  return t;
}

// The sun as cloud_march takes it: the atmosphere's sun light, else the first directional one.
CloudReference::CloudReference(const Scene& scene, const CloudReferenceSettings& settings)
    : layer_(scene.clouds ? *scene.clouds : throw std::invalid_argument("CloudReference: the scene has no cloud layer")),
      settings_(settings),
      camera_(scene.camera.position),
      radius_(scene.atmosphere ? scene.atmosphere->bottom_radius : kEarthRadius),
      origin_altitude_(scene.atmosphere ? scene.atmosphere->origin_altitude : 0),
      shape_(cloud_shape_texture(settings.shape_size, settings.seed)),
      detail_(cloud_detail_texture(settings.detail_size, settings.seed)),
      curl_(cloud_curl_texture(settings.curl_size, settings.seed)) {
  if (layer_.weather_map) weather_ = cloud_weather_texture(*layer_.weather_map, settings.weather_size);
  int sun = scene.atmosphere ? scene.atmosphere->sun_light : -1;
  for (size_t i = 0; sun < 0 && i < scene.lights.size(); ++i)
    if (scene.lights[i].type == LightType::directional) sun = int(i);
  if (sun >= 0) {
    const Light& light = scene.lights[size_t(sun)];
    has_sun_ = true;
    to_sun_ = scaled(physics::normalize(light.direction), -1);
    sun_irradiance_ = light.irradiance;
  }
  // With an atmosphere: its sun through the air above the layer, its sky added to the
  // ambient, by cloud_march's functions (physics/atmosphere_lighting.h).
  const physics::LightAtAltitude air = physics::atmosphere_light_at_altitude(scene, physics::cloud_light_altitude(layer_));
  if (air.has_sun) sun_irradiance_ = air.sun_irradiance;
  settings_.ambient = add(settings_.ambient, air.sky_radiance);
}

double CloudReference::altitude(const Vec3& p) const {
  const Vec3 from_centre = {p[0], p[1] + radius_ + origin_altitude_, p[2]};
  return std::sqrt(dot(from_centre, from_centre)) - radius_;
}

// cloud_march.comp's layer_segment, in double.
bool CloudReference::segment(const Vec3& o, const Vec3& d, double& t_in, double& t_out) const {
  const Vec3 centre{0, -(radius_ + origin_altitude_), 0};
  const double h = altitude(o), bottom = layer_.bottom_altitude, top = layer_.top_altitude;
  double b0 = 0, b1 = 0, u0 = 0, u1 = 0, g0 = 0, g1 = 0;
  const bool meets_bottom = sphere_roots(o, d, centre, radius_ + bottom, b0, b1);
  const bool meets_top = sphere_roots(o, d, centre, radius_ + top, u0, u1);
  const bool ground = h >= 0 && sphere_roots(o, d, centre, radius_, g0, g1) && g1 > 0;
  if (h < bottom) {
    if (ground || !meets_bottom || !meets_top) return false;
    t_in = b1;
    t_out = u1;
  } else if (h <= top) {
    t_in = 0;
    t_out = (meets_bottom && b0 > 0) ? b0 : (meets_top ? u1 : 0);
  } else {
    if (!meets_top || u0 <= 0) return false;
    t_in = u0;
    t_out = (meets_bottom && b0 > 0) ? b0 : u1;
  }
  return t_out > t_in;
}

// cloud_layer.glsl's coverage_and_type() at the noise's point (wind included): the layer's,
// or with a weather map coverage × r and mix(type, g, a) at (x + offset x, z + offset z) / size.
std::array<float, 2> CloudReference::coverage_and_type(const Vec3& np) const {
  if (!weather_) return {float(layer_.coverage), float(layer_.type)};
  const CloudWeatherMap& map = *layer_.weather_map;
  const float inverse_size = float(1.0 / map.size);  // the shader's params.weather.x
  const std::array<float, 4> w = weather_->sample((np[0] + map.offset[0]) * inverse_size, (np[2] + map.offset[1]) * inverse_size, 0);
  return {float(layer_.coverage) * w[0], float(layer_.type) * (1 - w[3]) + w[1] * w[3]};
}

// cloud_march.comp's density(): the shape's base, eroded by the curl-shifted detail.
double CloudReference::density(const Vec3& p) const {
  const double a = altitude(p);
  const double seconds = settings_.seconds;
  const Vec3 np{p[0] + layer_.wind[0] * seconds, a + layer_.wind[1] * seconds, p[2] + layer_.wind[2] * seconds};
  const float h = density_fn::cloud_height_fraction(float(a), float(layer_.bottom_altitude), float(layer_.top_altitude));
  const std::array<float, 4> s = shape_.sample(np[0] / layer_.shape_scale, np[1] / layer_.shape_scale, np[2] / layer_.shape_scale);
  const std::array<float, 2> here = coverage_and_type(np);
  const float base = density_fn::cloud_base_density(glm::vec4(s[0], s[1], s[2], s[3]), h, here[0], here[1]);
  if (base <= 0) return 0;
  const Vec3 q = scaled(np, 1 / layer_.detail_scale);
  const std::array<float, 4> c = curl_.sample(q[0], q[2], 0);
  const double shift = settings_.curl_strength * (1 - h);
  const std::array<float, 4> dt = detail_.sample(q[0] + shift * (c[0] * 2 - 1), q[1], q[2] + shift * (c[1] * 2 - 1));
  return density_fn::cloud_eroded_density(base, glm::vec4(dt[0], dt[1], dt[2], dt[3]), h);
}

// The sun's optical depth over light_distance, light_steps midpoint samples; ∞ where the
// ground hides the sun.
double CloudReference::sun_optical_depth(const Vec3& p) const {
  if (ground_hides_sun(p)) return std::numeric_limits<double>::infinity();
  const int n = std::max(settings_.light_steps, 1);
  const double ds = settings_.light_distance / n;
  double tau = 0;
  for (int j = 0; j < n; ++j) tau += layer_.extinction * density(add(p, scaled(to_sun_, (j + 0.5) * ds))) * ds;
  return tau;
}

bool CloudReference::ground_hides_sun(const Vec3& p) const {
  const Vec3 centre{0, -(radius_ + origin_altitude_), 0};
  double g0 = 0, g1 = 0;
  return altitude(p) >= 0 && sphere_roots(p, to_sun_, centre, radius_, g0, g1) && g1 > 0;
}

// cloud_march.comp's source(): the sun through the octaves (powder off) plus the ambient.
Vec3 CloudReference::source(const Vec3& p, double rho, double cos_theta) const {
  const float sigma_s = density_fn::cloud_scattering(float(layer_.extinction), float(rho));
  Vec3 s = scaled(settings_.ambient, sigma_s);
  if (!has_sun_) return s;
  const double tau = sun_optical_depth(p);
  if (!std::isfinite(tau)) return s;
  const CloudReferenceSettings& k = settings_;
  if (k.phase_table) {  // the table's phase at θ (cloud_march_body.glsl's phase_table_at), per channel
    const std::array<float, 3> p = physics::cloud_phase_table_at(*k.phase_table, float(cos_theta));
    const glm::vec3 lit = lighting::cloud_octaves_tabulated(sigma_s, float(tau), glm::vec3(p[0], p[1], p[2]), k.octaves, float(k.a),
                                                            float(k.b), float(k.c));
    return add(s, Vec3{sun_irradiance_[0] * lit.x, sun_irradiance_[1] * lit.y, sun_irradiance_[2] * lit.z});
  }
  const double lit = lighting::cloud_octaves(sigma_s, float(tau), float(cos_theta), float(k.g_forward), float(k.g_back),
                                             float(k.back_weight), k.octaves, float(k.a), float(k.b), float(k.c));
  return add(s, scaled(sun_irradiance_, lit));
}

CloudSample CloudReference::along(const Vec3& d, double surface) const {
  CloudSample out;
  double t_in = 0, t_out = 0;
  if (layer_.coverage <= 0 || !segment(camera_, d, t_in, t_out)) return out;
  t_out = std::min(t_out, std::min(surface, settings_.max_distance));
  if (!(t_out > t_in)) return out;
  const int n = std::max(settings_.view_steps, 1);
  const double dt = (t_out - t_in) / n;
  const double cos_theta = dot(to_sun_, d);
  for (int i = 0; i < n; ++i) {  // no skipping, no early termination
    const Vec3 p = add(camera_, scaled(d, t_in + (i + 0.5) * dt));
    const double rho = density(p);
    if (rho <= 0) continue;
    const double sigma_t = layer_.extinction * rho;
    const double step_t = std::exp(-sigma_t * dt);
    const double w = out.transmittance * (1 - step_t) / sigma_t;  // Hillaire's step, exact for J and σt constant on it
    out.radiance = add(out.radiance, scaled(source(p, rho, cos_theta), w));
    out.transmittance *= step_t;
  }
  return out;
}

}  // namespace volgraph::reference
