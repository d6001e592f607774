#include "physics/light_transmittance.h"

#include <algorithm>
#include <cmath>

#include "physics/lighting.h"
#include "physics/media.h"
#include "physics/media_field.h"

namespace volgraph::physics {

double light_march_length(const Light& light, const Vec3& p, double max_distance) {
  if (light.type == LightType::directional) return max_distance;
  return glm::length(vec(light.position) - vec(p));
}

Vec3 optical_depth_along(const MediaField& field, const Vec3& p, const Vec3& direction, double length, int steps, double jitter) {
  glm::dvec3 optical_depth(0);
  if (steps <= 0) return to_vec3(optical_depth);
  const double step_length = length / steps;
  for (int k = 0; k < steps; ++k) {
    const MediaSample s = field.sample(to_vec3(vec(p) + vec(direction) * ((k + jitter) * step_length)));
    optical_depth += vec(s.sigma_t()) * step_length;
  }
  return to_vec3(optical_depth);
}

Media media_toward_light(const Media& media, const Light& light) {
  Media marched = media;
  if (light.type == LightType::directional) marched.fog.reset();
  return marched;
}

Vec3 transmittance_to_light(const Media& media, const Light& light, const Vec3& p, int steps, double max_distance, double jitter) {
  if (steps <= 0) return {1, 1, 1};
  const MediaField field(media_toward_light(media, light));
  const Vec3 to_light = to_vec3(-vec(light_arriving(light, p).travel));
  const glm::dvec3 optical_depth =
      vec(optical_depth_along(field, p, to_light, light_march_length(light, p, max_distance), steps, jitter));
  return to_vec3(glm::exp(-glm::min(optical_depth, kMaxExponent<double>)));
}

}  // namespace volgraph::physics
