#include "passes/plumbing/scene_lighting.h"

#include "passes/plumbing/light_list.h"
#include "physics/atmosphere_lighting.h"
#include "physics/media_field.h"

namespace volgraph::plumbing {

std::vector<Light> SceneLighting::lights(const Scene& scene) const { return physics::lights_through_atmosphere(scene); }

Vec3 SceneLighting::sky_ambient_radiance(const Scene& scene) {
  const uint64_t hash = scene.hash(part_bit(ScenePart::atmosphere));
  if (atmosphere_hash_ != hash) {
    sky_ambient_ = physics::sky_ambient_radiance(scene);
    atmosphere_hash_ = hash;
  }
  return sky_ambient_;
}

gpu::SceneFrame SceneLighting::scene_frame(const Scene& scene, const physics::Mat4& view_projection, const std::array<double, 3>& ambient) {
  gpu::SceneFrame f{};
  physics::to_floats(view_projection, f.view_projection);
  // A surface facing any way receives π times the sky's isotropic radiance.
  const Vec3 sky = sky_ambient_radiance(scene);
  for (size_t i = 0; i < 3; ++i) f.ambient_irradiance[i] = float(ambient[i] + M_PI * sky[i]);
  f.light_list = pack_lights(lights(scene));
  Media fogs = scene.media;
  fogs.volumes.clear();
  f.media = physics::pack_media(fogs);
  return f;
}

}  // namespace volgraph::plumbing
