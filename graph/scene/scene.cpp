#include "graph/scene/scene.h"

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
    if (m && m->transmission > 0) f |= feature_bit(SceneFeature::translucent_objects);
  }
  return f;
}

}  // namespace volgraph
