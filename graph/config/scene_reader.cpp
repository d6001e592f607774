#include "graph/config/scene_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics/media.h"  // header-only: sigma from a transmittance colour
#include "physics/lighting.h"  // header-only: the light limit
#include "physics/noise.h"  // header-only: the octave limit

namespace volgraph::config {
namespace {

constexpr double kHuge = 1e9;            // metres: well past any scene
constexpr double kMaxRadiance = 1e9;
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

void read_material(const Node& n, const std::string& name, Material& m) {
  if (!n.object({"albedo", "albedo_texture", "emissive", "transmission", "ior"})) return;
  m.name = name;
  m.where = n.where();
  read(n, "albedo", m.albedo, 0, 1);
  if (auto t = n.member("albedo_texture")) {
    if (auto path = t->existing_path()) m.albedo_texture = *path;
  }
  read(n, "emissive", m.emissive, 0, kMaxRadiance);
  read(n, "transmission", m.transmission, 0, 1);
  read(n, "ior", m.ior, 1, 4);
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

}  // namespace

void read_scene(const Node& n, Scene& scene) {
  if (!n.object({"camera", "background", "materials", "objects", "lights", "media"})) return;
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
      scene.lights.push_back(l);
    }
    if (scene.lights.size() > size_t(physics::kMaxLights)) {
      lights->error("at most " + std::to_string(physics::kMaxLights) + " lights, got " + std::to_string(scene.lights.size()));
    }
  }
  if (auto media = n.member("media")) {
    scene.media = Media{};
    read_media(*media, scene.media);
  }
}

}  // namespace volgraph::config
