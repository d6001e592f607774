#include "passes/plumbing/light_list.h"

#include <cmath>
#include <string>

#include <stdexcept>
#include "physics/camera.h"

namespace volgraph::plumbing {

using namespace physics;  // the CPU maths these helpers are written in
namespace {

gpu::Light gpu_light(const Light& l) {
  gpu::Light g{};
  const bool directional = l.type == LightType::directional;
  const Vec3 dir = normalize(l.direction);
  const Vec3& power = directional ? l.irradiance : l.intensity;
  const float type = directional ? 0.0f : l.type == LightType::point ? 1.0f : 2.0f;
  for (size_t i = 0; i < 3; ++i) {
    g.position_type[i] = float(l.position[i]);
    g.direction_cos_outer[i] = float(dir[i]);
    g.power_cos_inner[i] = float(power[i]);
  }
  g.position_type[3] = type;
  g.direction_cos_outer[3] = float(std::cos(l.outer_cone_deg * M_PI / 180));
  g.power_cos_inner[3] = float(std::cos(l.inner_cone_deg * M_PI / 180));
  return g;
}

}  // namespace

gpu::LightList pack_lights(const std::vector<Light>& lights) {
  if (lights.size() > size_t(kMaxLights)) {
    throw std::logic_error("at most " + std::to_string(kMaxLights) + " lights");
  }
  gpu::LightList list{};
  list.counts[0] = int32_t(lights.size());
  for (size_t i = 0; i < lights.size(); ++i) list.lights[i] = gpu_light(lights[i]);
  return list;
}

}  // namespace volgraph::plumbing
