// The light the passes shade the scene with (physics/atmosphere_lighting.h): its lights
// with the atmosphere's sun dimmed by the air, and the sky's ambient radiance — which
// takes the CPU ~10 ms (Ψ_ms's sphere of rays), so it is kept until the atmosphere or its
// sun changes (Scene::hash of ScenePart::atmosphere).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <array>

#include "graph/scene/scene.h"
#include "physics/camera.h"
#include "shaders/include/scene_frame.h"

namespace volgraph::plumbing {

class SceneLighting {
 public:
  std::vector<Light> lights(const Scene& scene) const;
  // W/(m²·sr) per channel: media scatter σs times it, a surface receives π times it.
  Vec3 sky_ambient_radiance(const Scene& scene);
  // The opaque surfaces' lighting block seen through `view_projection` (the scene pass's
  // camera, a probe's face): the lights, π·(sky) + `ambient` irradiance, the global and
  // height fog in closed form (the local volumes only through an opacity shadow map).
  gpu::SceneFrame scene_frame(const Scene& scene, const physics::Mat4& view_projection, const std::array<double, 3>& ambient);

 private:
  std::optional<uint64_t> atmosphere_hash_;
  Vec3 sky_ambient_{0, 0, 0};
};

}  // namespace volgraph::plumbing
