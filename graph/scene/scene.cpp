#include "graph/scene/scene.h"

#include <filesystem>

namespace volgraph {
namespace {

bool any_positive(const Vec3& v) { return v[0] > 0 || v[1] > 0 || v[2] > 0; }

bool has_medium(const Medium& m) {
  return any_positive(m.sigma_s) || any_positive(m.sigma_a) || any_positive(m.emission);
}

}  // namespace

const Material* Scene::find_material(const std::string& name) const {
  for (const Material& m : materials) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

int Scene::sun_light() const {
  if (atmosphere && atmosphere->sun_light >= 0) return atmosphere->sun_light;
  for (size_t i = 0; i < lights.size(); ++i)
    if (lights[i].type == LightType::directional) return int(i);
  return -1;
}

SceneFeatures Scene::features() const {
  SceneFeatures f = 0;
  if (!objects.empty()) f |= feature_bit(SceneFeature::geometry);
  if (!lights.empty()) f |= feature_bit(SceneFeature::lights);
  for (const Light& l : lights) {
    if (l.cast_shadows && l.type != LightType::point) f |= feature_bit(SceneFeature::shadow_casting_light);
  }
  bool local = false;
  for (const MediumVolume& v : media.volumes) local = local || has_medium(v.medium);
  const bool global = (media.fog && has_medium(*media.fog)) || (media.height_fog && has_medium(media.height_fog->medium));
  if (global || local) f |= feature_bit(SceneFeature::medium);
  if (local) f |= feature_bit(SceneFeature::local_volumes);
  for (const Object& o : objects) {
    const Material* m = find_material(o.material);
    if ((m && m->translucency.translucent()) || o.translucent_in_file) f |= feature_bit(SceneFeature::translucent_objects);
  }
  if (atmosphere) f |= feature_bit(SceneFeature::atmosphere);
  if (clouds) f |= feature_bit(SceneFeature::clouds);
  return f;
}

}  // namespace volgraph

namespace volgraph {
namespace {

// FNV-1a over the values of a scene part, field by field (Where and names excluded:
// they do not change what a pass computes).
class SceneHasher {
 public:
  uint64_t value() const { return h_; }
  void add(const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
  }
  void add(double v) { add(&v, sizeof v); }
  void add(int64_t v) { add(&v, sizeof v); }
  void add(bool v) { add(int64_t(v)); }
  void add(const Vec3& v) { add(v.data(), sizeof(double) * 3); }
  void add(const std::string& s) {
    add(int64_t(s.size()));
    add(s.data(), s.size());
  }
  void add(const Transform& t) {
    add(t.translate);
    add(t.rotate_deg);
    add(t.scale);
  }
  void add(const DensityLayer& l) {
    add(l.width);
    add(l.exp_term);
    add(l.exp_scale);
    add(l.linear_term);
    add(l.constant_term);
  }
  void add(const DensityProfile& p) {
    add(p.lower);
    add(p.upper);
  }
  void add(const Medium& m) {
    add(m.sigma_s);
    add(m.sigma_a);
    add(m.g);
    add(m.emission);
  }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

void hash_camera(SceneHasher& h, const Camera& c) {
  h.add(c.position);
  h.add(c.target);
  h.add(c.up);
  h.add(c.fov_y_deg);
  h.add(c.near);
  h.add(c.far);
}

void hash_lights(SceneHasher& h, const std::vector<Light>& lights) {
  h.add(int64_t(lights.size()));
  for (const Light& l : lights) {
    h.add(int64_t(l.type));
    h.add(l.direction);
    h.add(l.position);
    h.add(l.irradiance);
    h.add(l.intensity);
    h.add(l.inner_cone_deg);
    h.add(l.outer_cone_deg);
    h.add(l.cast_shadows);
  }
}

void hash_media(SceneHasher& h, const Media& media) {
  h.add(media.fog.has_value());
  if (media.fog) h.add(*media.fog);
  h.add(media.height_fog.has_value());
  if (media.height_fog) {
    h.add(media.height_fog->medium);
    h.add(media.height_fog->base_height);
    h.add(media.height_fog->falloff);
  }
  h.add(int64_t(media.volumes.size()));
  for (const MediumVolume& v : media.volumes) {
    h.add(int64_t(v.shape));
    h.add(v.size);
    h.add(v.transform);
    h.add(v.medium);
    h.add(int64_t(v.noise.octaves));
    h.add(v.noise.scale);
    h.add(v.noise.coverage);
    h.add(v.noise.edge_fade);
  }
}

void hash_geometry(SceneHasher& h, const Scene& scene) {
  h.add(int64_t(scene.materials.size()));
  for (const Material& m : scene.materials) {
    h.add(m.name);
    h.add(m.albedo);
    h.add(m.albedo_texture);
    h.add(m.emissive);
    const Translucency& t = m.translucency;
    h.add(t.alpha);
    h.add(int64_t(t.alpha_mode));
    h.add(t.alpha_cutoff);
    h.add(t.transmission);
    h.add(t.ior);
    h.add(t.dispersion);
    h.add(t.attenuation_color);
    h.add(t.attenuation_distance);
    h.add(int64_t(t.volume));
    h.add(t.thickness);
  }
  h.add(int64_t(scene.objects.size()));
  for (const Object& o : scene.objects) {
    h.add(int64_t(o.shape));
    h.add(o.size);
    h.add(o.file);
    h.add(o.material);
    h.add(o.transform);
    h.add(o.cast_shadows);
  }
}

// The atmosphere's values (its preset's name excluded: the values are what it gave) and
// its sun: the light's direction and irradiance, which the sky's LUTs depend on.
void hash_atmosphere(SceneHasher& h, const std::optional<Atmosphere>& atmosphere, const std::vector<Light>& lights) {
  h.add(atmosphere.has_value());
  if (!atmosphere) return;
  const Atmosphere& a = *atmosphere;
  h.add(a.bottom_radius);
  h.add(a.top_radius);
  h.add(a.rayleigh_scattering);
  h.add(a.rayleigh_density);
  h.add(a.mie_scattering);
  h.add(a.mie_extinction);
  h.add(a.mie_density);
  h.add(a.mie_g);
  h.add(int64_t(a.mie_phase));
  h.add(a.absorption_extinction);
  h.add(a.absorption_density);
  h.add(a.ground_albedo);
  h.add(a.origin_altitude);
  h.add(a.sun_angular_radius);
  const bool has_sun = a.sun_light >= 0 && size_t(a.sun_light) < lights.size();
  h.add(has_sun);
  if (!has_sun) return;
  h.add(lights[size_t(a.sun_light)].direction);
  h.add(lights[size_t(a.sun_light)].irradiance);
}

void hash_clouds(SceneHasher& h, const std::optional<CloudLayer>& clouds) {
  h.add(clouds.has_value());
  if (!clouds) return;
  const CloudLayer& c = *clouds;
  for (const double v : {c.bottom_altitude, c.top_altitude, c.coverage, c.type, c.extinction, c.shape_scale, c.detail_scale}) h.add(v);
  h.add(c.wind);
  h.add(c.weather_map.has_value());
  if (!c.weather_map) return;
  h.add(c.weather_map->image);
  for (const double v : {c.weather_map->size, c.weather_map->offset[0], c.weather_map->offset[1]}) h.add(v);
}

// A file's path, size and time of last change (a rewritten file hashes anew); -1 for none.
void hash_file(SceneHasher& h, const std::string& path) {
  h.add(path);
  std::error_code error;
  const auto bytes = std::filesystem::file_size(path, error);
  h.add(int64_t(error ? -1 : int64_t(bytes)));
  const auto changed = std::filesystem::last_write_time(path, error);
  h.add(int64_t(error ? -1 : int64_t(changed.time_since_epoch().count())));
}

// The volume file and the 2D table's image (hash_file), the layout and window (a detached
// NRRD data file is not watched).
void hash_volume_data(SceneHasher& h, const std::optional<VolumeData>& volume) {
  h.add(volume.has_value());
  if (!volume) return;
  const VolumeData& v = *volume;
  hash_file(h, v.file);
  h.add(v.window.has_value());
  if (v.window) h.add((*v.window)[0]), h.add((*v.window)[1]);
  h.add(v.raw);
  h.add(v.raw_type);
  for (const int64_t n : v.raw_sizes) h.add(n);
  h.add(v.raw_spacing);
  h.add(v.raw_big_endian);
  hash_file(h, v.transfer_2d);
}

}  // namespace

uint64_t Scene::hash(ScenePartMask parts) const {
  SceneHasher h;
  h.add(int64_t(parts));
  if (parts & part_bit(ScenePart::camera)) hash_camera(h, camera);
  if (parts & part_bit(ScenePart::lights)) hash_lights(h, lights);
  if (parts & part_bit(ScenePart::media)) hash_media(h, media);
  if (parts & part_bit(ScenePart::geometry)) hash_geometry(h, *this);
  if (parts & part_bit(ScenePart::background)) h.add(background);
  if (parts & part_bit(ScenePart::atmosphere)) hash_atmosphere(h, atmosphere, lights);
  if (parts & part_bit(ScenePart::clouds)) hash_clouds(h, clouds);
  if (parts & part_bit(ScenePart::volume_data)) hash_volume_data(h, volume_data);
  return h.value();
}

}  // namespace volgraph
