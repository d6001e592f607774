#include "graph/config/scene_reader.h"

#include <filesystem>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/atmosphere.h"  // the atmosphere's presets
#include "physics/media.h"  // header-only: sigma from a transmittance colour
#include "physics/lighting.h"  // header-only: the light limit
#include "physics/noise.h"  // header-only: the octave limit
#include "physics/sun_position.h"  // header-only: the sun from the time of day

namespace volgraph::config {
namespace {

constexpr double kHuge = 1e9;            // metres: well past any scene
constexpr double kMaxRadiance = 1e9;
// A surface's emission lands in half-float colour targets: above 65504 it would be clamped.
constexpr double kMaxHalfRadiance = 65504;
constexpr double kMaxCoefficient = 1e6;  // 1/m
// Direction vectors shorter than this have no usable direction: normalising them in
// float (the GPU) underflows, in double (the reference) loses every digit.
constexpr double kMinDirectionLength = 1e-6;
// The camera's up may not lie within this sine of its view direction (about 0.006°):
// the view basis takes its right vector from their cross product, which the GPU
// computes in float (relative error near 1e-7), so closer than this its direction is
// mostly rounding; exactly parallel, it is zero.
constexpr double kMinUpSine = 1e-4;

// far / near at most this: the GPU's projection works in float, where far / (near − far)
// rounds to −1 once near / far falls toward float's epsilon (1.2e-7), and the depth
// buffer then holds no depth (fog_apply's depth_aware, measured on demo_raymarch_fog:
// unchanged up to 1e7, the frame darkened from 3e7); a factor 10 below that.
constexpr double kMaxFarOverNear = 1e6;
// A volume's largest extent over its smallest (size × transform scale) at most this: the
// GPU carries a volume's world-to-local transform in float, which loses a thin axis
// past it (demo_fog's ball: within 0.1 % of the reference's mean up to 1e5, 2.5 % off at
// 1e6, the whole frame darkened at 1e8; the reference's mean does not change).
constexpr double kMaxVolumeAnisotropy = 1e4;

std::string short_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

double length(const Vec3& v) { return std::hypot(v[0], v[1], v[2]); }

// A direction of length ≥ kMinDirectionLength at member `key` (when present).
void check_direction(const Node& obj, const char* key, const Vec3& v, const char* what) {
  const auto member = obj.member(key);
  if (!member || length(v) >= kMinDirectionLength) return;
  member->error(std::string(what) + " has length " + short_number(length(v)) + "; expected a direction of length at least 1e-6");
}

template <typename Enum>
std::optional<Enum> choice(const Node& n, const std::vector<std::pair<std::string, Enum>>& options) {
  const auto text = n.string();
  if (!text) return std::nullopt;
  std::vector<std::string> names;
  for (const auto& [name, value] : options) {
    if (name == *text) return value;
    names.push_back(name);
  }
  n.error("unknown value \"" + *text + "\"" + did_you_mean(*text, names) + "; expected " + one_of(names));
  return std::nullopt;
}

void read_transform(const Node& obj, Transform& t) {
  if (!obj.object({"translate", "rotate_deg", "scale"})) return;
  read(obj, "translate", t.translate, -kHuge, kHuge);
  read(obj, "rotate_deg", t.rotate_deg, -3600, 3600);
  read(obj, "scale", t.scale, 1e-6, kHuge);
}

void read_camera(const Node& n, Camera& c) {
  if (!n.object({"position", "target", "up", "fov_y_deg", "near", "far"})) return;
  read(n, "position", c.position, -kHuge, kHuge);
  read(n, "target", c.target, -kHuge, kHuge);
  read(n, "up", c.up, -1e3, 1e3);
  read(n, "fov_y_deg", c.fov_y_deg, 1, 179);
  read(n, "near", c.near, 1e-4, 1e6);
  read(n, "far", c.far, 1e-3, kHuge);
  const Vec3 view{c.target[0] - c.position[0], c.target[1] - c.position[1], c.target[2] - c.position[2]};
  check_direction(n, "up", c.up, "camera up");
  if (length(view) < kMinDirectionLength) {
    n.error("camera target is within 1e-6 m of its position; expected a view direction (target − position) of length at least 1e-6");
  } else if (length(c.up) >= kMinDirectionLength) {
    const Vec3 v = physics::scaled(view, 1 / length(view)), u = physics::scaled(c.up, 1 / length(c.up));
    if (length(physics::cross(v, u)) < kMinUpSine) {
      n.error("camera up is parallel to the view direction (target − position); expected an up at least 0.006° (sine 1e-4) away from it");
    }
  }
  if (c.far <= c.near) {
    n.error("camera far (" + std::to_string(c.far) + ") must exceed near (" + std::to_string(c.near) + ")");
  } else if (c.far > kMaxFarOverNear * c.near) {
    n.error("camera far / near is " + short_number(c.far / c.near) +
            "; expected at most 1e6 (the GPU's float depth cannot tell depths apart past that)");
  }
}

// glTF's alphaMode, KHR_materials_transmission, _ior and _volume, as config keys. An
// `alpha` below 1 without an `alpha_mode` blends (the only mode where it shows).
void read_translucency(const Node& n, Translucency& t) {
  read(n, "alpha", t.alpha, 0, 1);
  if (t.alpha < 1) t.alpha_mode = AlphaMode::blend;
  if (const auto mode = n.member("alpha_mode")) {
    if (auto m = choice<AlphaMode>(*mode, {{"opaque", AlphaMode::opaque}, {"mask", AlphaMode::mask}, {"blend", AlphaMode::blend}})) {
      t.alpha_mode = *m;
    }
  }
  read(n, "alpha_cutoff", t.alpha_cutoff, 0, 1);
  read(n, "transmission", t.transmission, 0, 1);
  read(n, "ior", t.ior, 1, 4);
  read(n, "dispersion", t.dispersion, 0, kHuge);  // KHR_materials_dispersion: ≥ 0
  read(n, "roughness", t.roughness, 0, 1);
  // 0 is allowed: the medium absorbs everything past its surface (physics::sigma_t_from_color).
  read(n, "attenuation_color", t.attenuation_color, 0, 1);
  read(n, "attenuation_distance", t.attenuation_distance, 1e-6, 1e30);
  read(n, "thickness", t.thickness, 0, kHuge);
  if (const auto volume = n.member("volume")) {
    if (auto v = choice<VolumeKind>(*volume, {{"thin_walled", VolumeKind::thin_walled}, {"shell", VolumeKind::shell}, {"solid", VolumeKind::solid}})) {
      t.volume = *v;
    }
    if (t.volume == VolumeKind::shell && t.thickness <= 0) {
      volume->error("a shell needs its wall's thickness; expected \"thickness\" > 0 m beside \"volume\": \"shell\"");
    }
  }
}

void read_material(const Node& n, const std::string& name, Material& m) {
  if (!n.object({"albedo", "albedo_texture", "emissive", "alpha", "alpha_mode", "alpha_cutoff", "transmission", "ior", "dispersion", "roughness",
                 "attenuation_color", "attenuation_distance", "volume", "thickness"})) {
    return;
  }
  m.name = name;
  m.where = n.where();
  read(n, "albedo", m.albedo, 0, 1);
  if (auto t = n.member("albedo_texture")) {
    if (auto path = t->existing_path()) m.albedo_texture = *path;
  }
  read(n, "emissive", m.emissive, 0, kMaxHalfRadiance);
  read_translucency(n, m.translucency);
}

void read_object(const Node& n, const Scene& scene, Object& o) {
  if (!n.object({"name", "shape", "size", "file", "material", "transform", "cast_shadows"})) return;
  o.where = n.where();
  read(n, "name", o.name);
  const auto shape_node = n.member("shape");
  if (!shape_node) {
    n.error("missing key \"shape\"; expected one of plane, box, sphere, gltf");
    return;
  }
  const auto shape = choice<Shape>(*shape_node, {{"plane", Shape::plane}, {"box", Shape::box},
                                                 {"sphere", Shape::sphere}, {"gltf", Shape::gltf}});
  if (!shape) return;
  o.shape = *shape;
  read(n, "size", o.size, 1e-6, kHuge);
  if (auto file = n.member("file")) {
    if (o.shape != Shape::gltf) file->error("\"file\" is only for shape \"gltf\"");
    else if (auto path = file->existing_path()) o.file = *path;
  } else if (o.shape == Shape::gltf) {
    n.error("missing key \"file\" (a .gltf or .glb path) for shape \"gltf\"");
  }
  if (auto mat = n.member("material")) {
    if (auto name = mat->string()) {
      std::vector<std::string> names;
      for (const Material& m : scene.materials) names.push_back(m.name);
      if (!scene.find_material(*name)) {
        mat->error("unknown material \"" + *name + "\"" + did_you_mean(*name, names) +
                   (names.empty() ? "; the scene defines no materials" : "; expected " + one_of(names)));
      }
      o.material = *name;
    }
  } else if (o.shape != Shape::gltf) {
    n.error("missing key \"material\"");
  }
  if (auto t = n.member("transform")) read_transform(*t, o.transform);
  read(n, "cast_shadows", o.cast_shadows);
}

void read_light(const Node& n, Light& l) {
  if (!n.object({"name", "type", "direction", "position", "irradiance", "intensity", "inner_cone_deg",
                 "outer_cone_deg", "cast_shadows"})) {
    return;
  }
  l.where = n.where();
  read(n, "name", l.name);
  const auto type_node = n.member("type");
  if (!type_node) {
    n.error("missing key \"type\"; expected one of directional, point, spot");
    return;
  }
  const auto type = choice<LightType>(
      *type_node, {{"directional", LightType::directional}, {"point", LightType::point}, {"spot", LightType::spot}});
  if (!type) return;
  l.type = *type;
  auto only_for = [&](const char* key, bool allowed, const char* which) {
    if (auto m = n.member(key); m && !allowed) m->error("\"" + std::string(key) + "\" is only for " + which + " lights");
  };
  const bool directional = l.type == LightType::directional, spot = l.type == LightType::spot;
  only_for("direction", !(l.type == LightType::point), "directional and spot");
  only_for("position", !directional, "point and spot");
  only_for("irradiance", directional, "directional");
  only_for("intensity", !directional, "point and spot");
  only_for("inner_cone_deg", spot, "spot");
  only_for("outer_cone_deg", spot, "spot");
  read(n, "direction", l.direction, -1e3, 1e3);
  read(n, "position", l.position, -kHuge, kHuge);
  read(n, "irradiance", l.irradiance, 0, kMaxRadiance);
  read(n, "intensity", l.intensity, 0, kMaxRadiance);
  read(n, "inner_cone_deg", l.inner_cone_deg, 0, 89.9);
  read(n, "outer_cone_deg", l.outer_cone_deg, 0.1, 89.9);
  read(n, "cast_shadows", l.cast_shadows);
  check_direction(n, "direction", l.direction, "light direction");
  if (spot && l.inner_cone_deg > l.outer_cone_deg) n.error("spot inner_cone_deg exceeds outer_cone_deg");
}

// The medium's σ from one of three inputs: σs and σa directly; albedo + extinction
// (σs = albedo·σt, σa = σt − σs); or albedo + the transmittance colour seen through a
// distance (RTR4 eq. 14.23: σt = −ln(colour)/distance, colour 0 as opaque as
// kMinTransmittance allows).
void read_coefficients(const Node& n, Medium& m) {
  const bool physical = n.member("sigma_s") || n.member("sigma_a");
  const bool extinction_given = n.member("extinction").has_value();
  const bool transmittance_given = n.member("transmittance").has_value();
  if (int(physical) + int(extinction_given) + int(transmittance_given) > 1) {
    n.error("give one of sigma_s/sigma_a, albedo + extinction, or albedo + transmittance");
    return;
  }
  read(n, "sigma_s", m.sigma_s, 0, kMaxCoefficient);
  read(n, "sigma_a", m.sigma_a, 0, kMaxCoefficient);
  if (physical) return;
  Vec3 albedo{1, 1, 1}, extinction{0, 0, 0};
  read(n, "albedo", albedo, 0, 1);
  read(n, "extinction", extinction, 0, kMaxCoefficient);
  if (auto t = n.member("transmittance"); t && t->object({"color", "distance"})) {
    Vec3 colour{1, 1, 1};
    double distance = 1;
    read(*t, "color", colour, 0, 1);
    read(*t, "distance", distance, 1e-6, kHuge);
    for (size_t c = 0; c < 3; ++c) extinction[c] = physics::sigma_t_from_transmittance(colour[c], distance);
  }
  for (size_t c = 0; c < 3; ++c) {
    m.sigma_s[c] = albedo[c] * extinction[c];
    m.sigma_a[c] = extinction[c] - m.sigma_s[c];
  }
}

void read_medium(const Node& n, Medium& m, std::initializer_list<const char*> extra_keys) {
  std::vector<const char*> keys = {"sigma_s", "sigma_a", "albedo", "extinction", "transmittance", "g", "emission"};
  keys.insert(keys.end(), extra_keys.begin(), extra_keys.end());
  if (!n.object_any_keys()) return;
  for (const auto& [key, value] : n.json().items()) {
    (void)value;
    bool known = false;
    for (const char* k : keys) known = known || key == k;
    if (!known) {
      std::vector<std::string> names(keys.begin(), keys.end());
      n.child(key).error("unknown key \"" + key + "\"" + did_you_mean(key, names) + "; expected " + one_of(names));
    }
  }
  if (n.member("albedo") && !n.member("extinction") && !n.member("transmittance")) {
    n.error("albedo needs extinction or transmittance beside it");
  }
  read_coefficients(n, m);
  read(n, "g", m.g, -0.999, 0.999);
  read(n, "emission", m.emission, 0, kMaxRadiance);
}

// A volume's "noise": fractal noise (octaves 1 … 8, scale, coverage) and the edge fade,
// which also applies without noise.
void read_noise(const Node& n, Noise& noise) {
  if (!n.object({"octaves", "scale", "coverage", "edge_fade"})) return;
  if (auto o = n.member("octaves")) {
    if (auto v = o->integer(1, physics::kMaxNoiseOctaves)) noise.octaves = int(*v);
  }
  read(n, "scale", noise.scale, 1e-3, kHuge);
  read(n, "coverage", noise.coverage, 0.01, 1);
  read(n, "edge_fade", noise.edge_fade, 0, kHuge);
  if (n.member("octaves")) return;
  for (const char* key : {"scale", "coverage"}) {
    if (auto m = n.member(key)) m->error("\"" + std::string(key) + "\" needs \"octaves\" (1 … 8) beside it: without octaves the volume has no noise");
  }
}

// A volume's extents along its own axes (size, a sphere's radius on all three, times the
// transform's scale) within kMaxVolumeAnisotropy of each other; a flat one (a size of 0)
// has no inside and is allowed.
void check_anisotropy(const Node& n, const MediumVolume& v) {
  Vec3 extent{};
  for (size_t k = 0; k < 3; ++k) extent[k] = (v.shape == Shape::sphere ? v.size[0] : v.size[k]) * v.transform.scale[k];
  const double smallest = std::min({extent[0], extent[1], extent[2]}), largest = std::max({extent[0], extent[1], extent[2]});
  if (!(smallest > 0) || largest <= kMaxVolumeAnisotropy * smallest) return;
  n.error("the volume's extents (size × transform scale) span a ratio of " + short_number(largest / smallest) +
          "; expected at most 1e4 (the GPU's float transform loses the thin axis past that)");
}

void read_media(const Node& n, Media& media) {
  if (!n.object({"fog", "height_fog", "volumes"})) return;
  if (auto f = n.member("fog")) {
    Medium m;
    read_medium(*f, m, {});
    media.fog = m;
  }
  if (auto f = n.member("height_fog")) {
    HeightFog h;
    read_medium(*f, h.medium, {"base_height", "falloff"});
    read(*f, "base_height", h.base_height, -kHuge, kHuge);
    read(*f, "falloff", h.falloff, 1e-6, 1e3);
    media.height_fog = h;
  }
  if (auto list = n.member("volumes"); list && list->array()) {
    for (size_t i = 0; i < list->size(); ++i) {
      const Node v = list->element(i);
      MediumVolume vol;
      vol.where = v.where();
      read_medium(v, vol.medium, {"shape", "size", "transform", "noise"});
      read(v, "size", vol.size, 0, kHuge);
      if (auto noise = v.member("noise")) read_noise(*noise, vol.noise);
      if (auto s = v.member("shape")) {
        if (auto shape = choice<Shape>(*s, {{"box", Shape::box}, {"sphere", Shape::sphere},
                                           {"ellipsoid", Shape::ellipsoid}})) {
          vol.shape = *shape;
        }
      }
      if (auto t = v.member("transform")) read_transform(*t, vol.transform);
      check_anisotropy(v, vol);
      media.volumes.push_back(vol);
    }
  }
}

// The atmosphere (scene.h Atmosphere). A planet's radius in [1 m, 1e9 m] (the loader's
// extent of any scene).
constexpr double kMinPlanetRadius = 1;
constexpr double kMaxPlanetRadius = kHuge;
// A scale height H of at least 1 mm keeps exp_scale = −1/H within float's range: the GPU
// multiplies it by altitudes down to 0, and −inf · 0 is NaN.
constexpr double kMinScaleHeight = 1e-3;
constexpr double kMaxSunAngularRadius = 0.5;  // rad: the disk's radius; the sun seen from 1 AU is 0.004675

// An interval whose ends may be open, with the unit its messages name.
struct Interval {
  double min, max;
  bool min_open = false, max_open = false;
  const char* unit = "";
};

std::string full_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

std::string interval_text(const Interval& r) {
  char text[96];
  std::snprintf(text, sizeof text, "%s%.9g, %.9g%s%s", r.min_open ? "(" : "[", r.min, r.max, r.max_open ? ")" : "]", r.unit);
  return text;
}

bool inside(double v, const Interval& r) {
  return std::isfinite(v) && (r.min_open ? v > r.min : v >= r.min) && (r.max_open ? v < r.max : v <= r.max);
}

// Member `key` (when present) into `out` when it is a number inside `range`; false when
// it is present and is not (one message: the interval and what was there).
bool read_in(const Node& obj, const char* key, double& out, const Interval& range) {
  const auto m = obj.member(key);
  if (!m) return true;
  const Json& j = m->json();
  if (j.is_number() && inside(j.get<double>(), range)) {
    out = j.get<double>();
    return true;
  }
  m->error("expected a number in " + interval_text(range) + ", got " + (j.is_number() ? j.dump() : describe(j)));
  return false;
}

// The first of `keys` the object has, else the object itself: where a message about
// values that belong together points.
Node first_member(const Node& n, std::initializer_list<const char*> keys) {
  for (const char* key : keys) {
    if (auto m = n.member(key)) return *m;
  }
  return n;
}

// One layer of a profile (Bruneton 2017's DensityProfileLayer); keys left out are 0. Its
// exponential may only decay with altitude: with exp_scale > 0, e^(exp_scale · h) leaves
// float's range once exp_scale · h > 88.7 (and times an exp_term of 0 gives NaN), and
// none of the model's layers (Rayleigh, Mie, the ozone tent) grows.
void read_layer(const Node& n, DensityLayer& layer, bool upper) {
  if (!n.object({"width", "exp_term", "exp_scale", "linear_term", "constant_term"})) return;
  layer = DensityLayer{};
  if (auto w = n.member("width"); w && upper) {
    w->error("the upper layer reaches the top of the atmosphere: it has no \"width\"");
  } else {
    read(n, "width", layer.width, 0, kHuge);
  }
  read(n, "exp_term", layer.exp_term, -kHuge, kHuge);
  read(n, "linear_term", layer.linear_term, -kHuge, kHuge);
  read(n, "constant_term", layer.constant_term, -kHuge, kHuge);
  if (auto e = n.member("exp_scale")) {
    const auto v = e->number(-kHuge, kHuge);
    if (v && *v > 0) {
      e->error("exp_scale is " + full_number(*v) + " 1/m; expected at most 0 (a layer's exponential may only decay with altitude)");
    } else if (v) {
      layer.exp_scale = *v;
    }
  }
}

// A profile `{"lower": layer, "upper": layer}`: it replaces the preset's, a layer left out
// is 0 (the upper alone is a profile from the ground up).
void read_profile(const Node& n, DensityProfile& profile) {
  if (!n.object({"lower", "upper"})) return;
  profile = DensityProfile{};
  if (auto l = n.member("lower")) read_layer(*l, profile.lower, false);
  if (auto u = n.member("upper")) read_layer(*u, profile.upper, true);
}

// `<x>_density` (a profile) or the shorthand `<x>_scale_height` H (m): e^(−h / H) from the
// ground up (Bruneton 2017's exponential layer: exp_term 1, exp_scale −1/H).
void read_density(const Node& n, const std::string& name, DensityProfile& profile) {
  const std::string profile_key = name + "_density", height_key = name + "_scale_height";
  const auto given = n.member(profile_key.c_str());
  const auto height = n.member(height_key.c_str());
  if (given && height) {
    height->error("give one of \"" + profile_key + "\" or \"" + height_key + "\"");
    return;
  }
  if (given) read_profile(*given, profile);
  double h = 0;
  if (height && read_in(n, height_key.c_str(), h, {kMinScaleHeight, kHuge, false, false, " m"})) {
    profile = DensityProfile{{}, {0, 1, -1 / h, 0, 0}};
  }
}

// The starting point: a preset (physics/atmosphere.h), or "custom": every coefficient and
// density 0, the rest as the earth's, the radii required.
std::optional<Atmosphere> atmosphere_start(const Node& n) {
  const std::vector<std::string> names = {"earth", "mars", "custom"};
  std::string name = "earth";
  if (auto p = n.member("preset")) {
    const auto text = p->string();
    if (!text) return std::nullopt;
    if (std::find(names.begin(), names.end(), *text) == names.end()) {
      p->error("unknown preset \"" + *text + "\"" + did_you_mean(*text, names) + "; expected " + one_of(names));
      return std::nullopt;
    }
    name = *text;
  }
  if (name != "custom") {
    std::optional<Atmosphere> preset = physics::atmosphere_preset(name);
    if (!preset) n.error("the atmosphere preset \"" + name + "\" is not available");
    return preset;
  }
  std::vector<std::string> missing;
  for (const char* key : {"bottom_radius", "top_radius"}) {
    if (!n.member(key)) missing.push_back(std::string("\"") + key + "\"");
  }
  if (!missing.empty()) {
    n.error("a \"custom\" atmosphere needs " + missing[0] + (missing.size() > 1 ? " and " + missing[1] : "") +
            " (it starts from no preset)");
    return std::nullopt;
  }
  Atmosphere a;
  a.preset = "custom";
  a.rayleigh_scattering = a.mie_scattering = a.mie_extinction = a.absorption_extinction = Vec3{0, 0, 0};
  a.rayleigh_density = a.mie_density = a.absorption_density = DensityProfile{};
  return a;
}

// In a custom atmosphere a coefficient given without its density scatters nowhere (the
// densities start at 0): one message names the first such pair.
void check_custom_densities(const Node& n) {
  const std::pair<const char*, const char*> pairs[] = {{"rayleigh_scattering", "rayleigh"},
                                                       {"mie_scattering", "mie"},
                                                       {"mie_extinction", "mie"},
                                                       {"absorption_extinction", "absorption"}};
  for (const auto& [coefficient, name] : pairs) {
    const std::string density = std::string(name) + "_density", height = std::string(name) + "_scale_height";
    if (!n.member(coefficient) || n.member(density.c_str()) || n.member(height.c_str())) continue;
    const std::string alternative = std::string(name) == "absorption" ? "" : " or \"" + height + "\"";
    n.member(coefficient)->error("\"" + std::string(coefficient) + "\" needs \"" + density + "\"" + alternative +
                                 " beside it: a custom atmosphere's densities start at 0");
    return;
  }
}

// The radii: positive, within [1 m, 1e9 m], the top above the ground; the scene's origin
// at or above the ground and below the top.
void check_radii(const Node& n, const Atmosphere& a, bool radii_read, bool origin_read) {
  if (!radii_read) return;
  if (a.top_radius <= a.bottom_radius) {
    first_member(n, {"top_radius", "bottom_radius"}).error("top_radius (" + full_number(a.top_radius) + " m) must exceed bottom_radius (" +
             full_number(a.bottom_radius) + " m)");
    return;
  }
  if (origin_read && a.origin_altitude >= a.top_radius - a.bottom_radius) {
    first_member(n, {"origin_altitude"}).error("origin_altitude (" + full_number(a.origin_altitude) +
                                       " m) must be below the top of the atmosphere (top_radius − bottom_radius = " +
                                       full_number(a.top_radius - a.bottom_radius) + " m)");
  }
}

// Mie scattering cannot exceed Mie extinction (extinction = scattering + absorption).
void check_mie(const Node& n, const Atmosphere& a) {
  for (size_t c = 0; c < 3; ++c) {
    if (a.mie_scattering[c] <= a.mie_extinction[c]) continue;
    first_member(n, {"mie_scattering", "mie_extinction"}).error("mie_scattering (" + full_number(a.mie_scattering[c]) + " 1/m in channel " + std::to_string(c) +
             ") exceeds mie_extinction (" + full_number(a.mie_extinction[c]) +
             "); expected scattering ≤ extinction (extinction = scattering + absorption)");
    return;
  }
}

std::string light_type_name(LightType t) {
  switch (t) {
    case LightType::directional: return "directional";
    case LightType::point: return "point";
    case LightType::spot: return "spot";
  }
  return "";
}

// The sun light's index: the light named by "light", else the first directional light.
std::optional<int> find_sun_light(const Node& atmosphere, const std::optional<Node>& light, const std::vector<Light>& lights) {
  if (!light) {
    for (size_t i = 0; i < lights.size(); ++i) {
      if (lights[i].type == LightType::directional) return int(i);
    }
    atmosphere.error("the atmosphere's sun is the scene's first directional light, and the scene has none; expected a "
                     "directional light in \"lights\" (or \"sun\": {\"light\": NAME})");
    return std::nullopt;
  }
  const auto name = light->string();
  if (!name) return std::nullopt;
  std::vector<std::string> names;
  for (size_t i = 0; i < lights.size(); ++i) {
    if (lights[i].name != *name) {
      if (!lights[i].name.empty()) names.push_back(lights[i].name);
      continue;
    }
    if (lights[i].type == LightType::directional) return int(i);
    light->error("the light \"" + *name + "\" is a " + light_type_name(lights[i].type) +
                 " light; the atmosphere's sun must be a directional light");
    return std::nullopt;
  }
  light->error("unknown light \"" + *name + "\"" + did_you_mean(*name, names) +
               (names.empty() ? "; the scene has no named lights" : "; expected " + one_of(names)));
  return std::nullopt;
}

// The sun's position from "time_of_day" (true solar time, hours in [0, 24)),
// "latitude_deg" and "day_of_year", all three together: they set the sun light's
// direction (physics/sun_position.h; below the horizon is night, and allowed).
void read_sun_position(const Node& sun, Light& light) {
  const char* keys[] = {"time_of_day", "latitude_deg", "day_of_year"};
  std::vector<std::string> given, missing;
  for (const char* key : keys) (sun.member(key) ? given : missing).push_back(key);
  if (given.empty()) return;
  if (!missing.empty()) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "\"" : ", \"") + m + "\"";
    sun.error("the sun's \"" + given[0] + "\" needs " + list +
              " beside it: time_of_day, latitude_deg and day_of_year set the sun light's direction together");
    return;
  }
  double hours = 0, latitude = 0;
  const bool hours_read = read_in(sun, "time_of_day", hours, {0, 24, false, true, " h"});
  const bool latitude_read = read_in(sun, "latitude_deg", latitude, {-90, 90, false, false, "°"});
  const auto day = sun.member("day_of_year")->integer(1, 366);
  if (!hours_read || !latitude_read || !day) return;
  const Vec3 toward_sun = physics::sun_direction(hours, latitude, int(*day));
  light.direction = physics::scaled(toward_sun, -1);  // the light travels away from the sun
}

// "sun": which directional light, its angular radius, and optionally its position by time.
void read_sun(const Node& atmosphere, Scene& scene, Atmosphere& a) {
  const auto sun = atmosphere.member("sun");
  if (sun && !sun->object({"light", "angular_radius", "time_of_day", "latitude_deg", "day_of_year"})) return;
  if (sun) read_in(*sun, "angular_radius", a.sun_angular_radius, {0, kMaxSunAngularRadius, true, false, " rad"});
  const auto index = find_sun_light(atmosphere, sun ? sun->member("light") : std::nullopt, scene.lights);
  if (!index) return;
  a.sun_light = *index;
  if (sun) read_sun_position(*sun, scene.lights[size_t(*index)]);
}

void read_atmosphere(const Node& n, Scene& scene) {
  if (!n.object({"preset", "bottom_radius", "top_radius", "rayleigh_scattering", "rayleigh_density",
                 "rayleigh_scale_height", "mie_scattering", "mie_extinction", "mie_density", "mie_scale_height",
                 "mie_g", "mie_phase", "absorption_extinction", "absorption_density", "ground_albedo",
                 "origin_altitude", "sun"})) {
    return;
  }
  std::optional<Atmosphere> start = atmosphere_start(n);
  if (!start) return;
  Atmosphere a = *start;
  a.where = n.where();
  const Interval radius{kMinPlanetRadius, kMaxPlanetRadius, false, false, " m"};
  const bool bottom_read = read_in(n, "bottom_radius", a.bottom_radius, radius);
  const bool top_read = read_in(n, "top_radius", a.top_radius, radius);
  read(n, "rayleigh_scattering", a.rayleigh_scattering, 0, kMaxCoefficient);
  read_density(n, "rayleigh", a.rayleigh_density);
  read(n, "mie_scattering", a.mie_scattering, 0, kMaxCoefficient);
  read(n, "mie_extinction", a.mie_extinction, 0, kMaxCoefficient);
  read_density(n, "mie", a.mie_density);
  read(n, "mie_g", a.mie_g, -0.999, 0.999);
  if (auto p = n.member("mie_phase")) {
    if (auto phase = choice<MiePhase>(*p, {{"henyey_greenstein", MiePhase::henyey_greenstein},
                                           {"cornette_shanks", MiePhase::cornette_shanks}})) {
      a.mie_phase = *phase;
    }
  }
  read(n, "absorption_extinction", a.absorption_extinction, 0, kMaxCoefficient);
  if (auto d = n.member("absorption_density")) read_profile(*d, a.absorption_density);
  read(n, "ground_albedo", a.ground_albedo, 0, 1);
  const bool origin_read = read_in(n, "origin_altitude", a.origin_altitude, {0, kHuge, false, false, " m"});
  if (a.preset == "custom") check_custom_densities(n);
  check_radii(n, a, bottom_read && top_read, origin_read);
  check_mie(n, a);
  read_sun(n, scene, a);
  scene.atmosphere = a;
}

// scene.clouds.weather_map: an existing image, the metres it spans (> 0) and an [x, z] offset.
std::optional<CloudWeatherMap> read_weather_map(const Node& n) {
  if (!n.object({"image", "size", "offset"})) return std::nullopt;
  CloudWeatherMap w;
  w.where = n.where();
  const auto image = n.member("image");
  if (!image) {
    n.error("missing key \"image\" (the weather map's image file, relative to the config)");
    return std::nullopt;
  }
  const auto path = image->existing_path();
  if (!path) return std::nullopt;
  w.image = *path;
  if (!read_in(n, "size", w.size, {0, 1e7, true, false, " m"})) return std::nullopt;
  if (auto offset = n.member("offset")) {
    const bool pair = offset->array() && offset->size() == 2 && offset->json()[0].is_number() && offset->json()[1].is_number();
    if (!pair) {
      offset->error("expected an array of 2 numbers [x, z] in metres, got " + offset->json().dump());
      return std::nullopt;
    }
    for (size_t i = 0; i < 2; ++i) {
      const auto v = offset->element(i).number(-1e9, 1e9);
      if (!v) return std::nullopt;
      w.offset[i] = *v;
    }
  }
  return w;
}

// The cloud layer (scene.clouds): altitudes in metres above the ground, the top above the
// bottom and both within 100 km (the layer lies in the air, not in space).
void read_clouds(const Node& n, Scene& scene) {
  if (!n.object({"bottom_altitude", "top_altitude", "coverage", "type", "extinction", "shape_scale", "detail_scale", "wind", "weather_map"}))
    return;
  CloudLayer c;
  c.where = n.where();
  const Interval altitude{0, 100000, false, false, " m"};
  const bool bottom_read = read_in(n, "bottom_altitude", c.bottom_altitude, altitude);
  const bool top_read = read_in(n, "top_altitude", c.top_altitude, altitude);
  read_in(n, "coverage", c.coverage, {0, 1});
  read_in(n, "type", c.type, {0, 1});
  read_in(n, "extinction", c.extinction, {0, 10, true, false, " /m"});
  read_in(n, "shape_scale", c.shape_scale, {1, 1e7, false, false, " m"});
  read_in(n, "detail_scale", c.detail_scale, {0.1, 1e6, false, false, " m"});
  read(n, "wind", c.wind, -1000, 1000);
  if (auto weather = n.member("weather_map")) {
    c.weather_map = read_weather_map(*weather);
    if (!c.weather_map) return;
  }
  if (bottom_read && top_read && c.top_altitude <= c.bottom_altitude) {
    first_member(n, {"top_altitude", "bottom_altitude"})
        .error("top_altitude (" + full_number(c.top_altitude) + " m) must exceed bottom_altitude (" + full_number(c.bottom_altitude) + " m)");
    return;
  }
  scene.clouds = c;
}

// scene.volume_data.raw: a headerless file's layout (sample type, sizes, spacing, endian).
bool read_raw_layout(const Node& n, VolumeData& v) {
  if (!n.object({"type", "sizes", "spacing", "endian"})) return false;
  if (auto type = n.member("type")) {
    const auto name = type->string();
    if (!name) return false;
    if (*name != "uchar" && *name != "ushort" && *name != "short" && *name != "float") {
      type->error("expected one of uchar, ushort, short, float, got \"" + *name + "\"");
      return false;
    }
    v.raw_type = *name;
  }
  const auto sizes = n.member("sizes");
  if (!sizes) {
    n.error("missing key \"sizes\" (the raw file's samples along x, y, z)");
    return false;
  }
  if (!sizes->array() || sizes->size() != 3) {
    sizes->error("expected an array of 3 whole numbers (samples along x, y, z), got " + sizes->json().dump());
    return false;
  }
  for (size_t i = 0; i < 3; ++i) {
    const auto size = sizes->element(i).integer(1, 16384);
    if (!size) return false;
    v.raw_sizes[i] = *size;
  }
  read(n, "spacing", v.raw_spacing, 1e-9, 1e9);
  if (auto endian = n.member("endian")) {
    const auto name = endian->string();
    if (!name || (*name != "little" && *name != "big")) {
      endian->error("expected \"little\" or \"big\"");
      return false;
    }
    v.raw_big_endian = *name == "big";
  }
  return true;
}

// scene.volume_data: a NRRD (.nrrd, .nhdr) or .raw file relative to the config, an optional
// window [low, high] mapped to [0, 1], a raw file's layout, and an optional 2D transfer
// table's image (transfer_2d: density along x, gradient magnitude up y). The file's own header is
// checked by volume_file (its scene check), where the message can say what the file holds.
void read_volume_data(const Node& n, Scene& scene) {
  if (!n.object({"file", "window", "raw", "transfer_2d"})) return;
  VolumeData v;
  v.where = n.where();
  const auto file = n.member("file");
  if (!file) {
    n.error("missing key \"file\" (a NRRD or .raw volume file, relative to the config)");
    return;
  }
  const auto path = file->existing_path();
  if (!path) return;
  v.file = *path;
  if (auto window = n.member("window")) {
    const bool pair = window->array() && window->size() == 2 && window->json()[0].is_number() && window->json()[1].is_number();
    if (!pair || !(window->json()[1].get<double>() > window->json()[0].get<double>())) {
      window->error("expected [low, high] with high > low (the sample values mapped to 0 and 1), got " + window->json().dump());
      return;
    }
    v.window = std::array<double, 2>{window->json()[0].get<double>(), window->json()[1].get<double>()};
  }
  v.raw = std::filesystem::path(v.file).extension() == ".raw";
  const auto raw = n.member("raw");
  if (v.raw && !raw) {
    n.error("a .raw file needs \"raw\": {\"type\", \"sizes\", \"spacing\", \"endian\"} (it has no header)");
    return;
  }
  if (!v.raw && raw) {
    raw->error("only a .raw file takes a layout here (a NRRD file's header gives its own)");
    return;
  }
  if (raw && !read_raw_layout(*raw, v)) return;
  if (auto table = n.member("transfer_2d")) {
    const auto image = table->existing_path();
    if (!image) return;
    v.transfer_2d = *image;
  }
  scene.volume_data = v;
}

}  // namespace

void read_scene(const Node& n, Scene& scene) {
  if (!n.object({"camera", "background", "materials", "objects", "lights", "media", "atmosphere", "clouds", "volume_data"})) return;
  if (auto c = n.member("camera")) {
    Camera camera;
    read_camera(*c, camera);
    scene.camera = camera;
  }
  if (auto b = n.member("background")) {
    if (b->object({"radiance"})) read(*b, "radiance", scene.background, 0, kMaxRadiance);
  }
  if (auto mats = n.member("materials"); mats && mats->object_any_keys()) {
    for (const auto& item : mats->json().items()) {
      const std::string name = item.key();
      Material m;
      read_material(mats->child(name), name, m);
      auto same = [&](const Material& x) { return x.name == name; };
      if (auto it = std::find_if(scene.materials.begin(), scene.materials.end(), same); it != scene.materials.end()) {
        *it = m;
      } else {
        scene.materials.push_back(m);
      }
    }
  }
  if (auto objs = n.member("objects"); objs && objs->array()) {
    for (size_t i = 0; i < objs->size(); ++i) {
      Object o;
      read_object(objs->element(i), scene, o);
      scene.objects.push_back(o);
    }
  }
  if (auto lights = n.member("lights"); lights && lights->array()) {
    for (size_t i = 0; i < lights->size(); ++i) {
      Light l;
      read_light(lights->element(i), l);
      // A named light replaces the light of that name read before (an include's), in place.
      auto same = [&](const Light& x) { return !l.name.empty() && x.name == l.name; };
      if (auto it = std::find_if(scene.lights.begin(), scene.lights.end(), same); it != scene.lights.end()) {
        *it = l;
      } else {
        scene.lights.push_back(l);
      }
    }
    if (scene.lights.size() > size_t(physics::kMaxLights)) {
      lights->error("at most " + std::to_string(physics::kMaxLights) + " lights, got " + std::to_string(scene.lights.size()));
    }
  }
  if (auto media = n.member("media")) {
    scene.media = Media{};
    read_media(*media, scene.media);
  }
  if (auto atmosphere = n.member("atmosphere")) {  // after the lights: its sun is one of them
    scene.atmosphere.reset();
    read_atmosphere(*atmosphere, scene);
  }
  if (auto clouds = n.member("clouds")) {
    scene.clouds.reset();
    read_clouds(*clouds, scene);
  }
  if (auto volume = n.member("volume_data")) {
    scene.volume_data.reset();
    read_volume_data(*volume, scene);
  }
}

}  // namespace volgraph::config
