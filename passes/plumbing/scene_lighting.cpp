#include "passes/plumbing/scene_lighting.h"

#include "physics/atmosphere_lighting.h"

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

}  // namespace volgraph::plumbing
