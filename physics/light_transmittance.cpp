#include "physics/light_transmittance.h"

#include <algorithm>
#include <cmath>

#include "physics/lighting.h"
#include "physics/media.h"
#include "physics/media_average.h"
#include "physics/media_field.h"

namespace volgraph::physics {
namespace {

// e^(−τ) per channel, τ clamped as the shaders clamp it.
Vec3 transmittance_of_depth(const glm::dvec3& optical_depth) {
  return to_vec3(glm::exp(-glm::min(optical_depth, glm::dvec3(kMaxExponent<double>))));
}

}  // namespace

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

Media local_volumes(const Media& media) {
  Media volumes = media;
  volumes.fog.reset();
  volumes.height_fog.reset();
  return volumes;
}

Vec3 fog_optical_depth_to_light(const Media& media, const Light& light, const Vec3& p) {
  const bool directional = light.type == LightType::directional;
  const glm::dvec3 to_light = directional ? -glm::normalize(vec(light.direction)) : vec(light.position) - vec(p);
  const double distance = directional ? 0.0 : glm::length(to_light);
  const double to_light_y = directional ? to_light.y : distance > 0 ? to_light.y / distance : 0.0;
  glm::dvec3 depth(0);
  if (media.fog && !directional) depth += (vec(media.fog->sigma_s) + vec(media.fog->sigma_a)) * distance;
  if (const std::optional<HeightFog>& h = media.height_fog) {
    const double unit_depth = directional ? height_fog_unit_depth_to_infinity(h->falloff, h->base_height, p[1], to_light_y)
                                          : height_fog_optical_depth(1.0, h->falloff, h->base_height, p[1], to_light_y, distance);
    depth += (vec(h->medium.sigma_s) + vec(h->medium.sigma_a)) * unit_depth;
  }
  return to_vec3(depth);
}

Vec3 volumes_optical_depth_to_light(const Media& media, const Light& light, const Vec3& p, int steps, double max_distance,
                                    double jitter) {
  if (steps <= 0 || media.volumes.empty()) return {0, 0, 0};
  const double length = light_march_length(light, p, max_distance);
  if (length <= 0) return {0, 0, 0};
  const MediaField field(local_volumes(media));
  const RaySegment segment{p, to_vec3(-vec(light_arriving(light, p).travel)), 0.0, length};
  glm::dvec3 optical_depth(0);
  for (size_t i = 0; i < media.volumes.size(); ++i) {
    const Medium& m = media.volumes[i].medium;
    optical_depth += (vec(m.sigma_s) + vec(m.sigma_a)) * (volume_mean_density(field, i, segment, jitter - 0.5, steps) * length);
  }
  return to_vec3(optical_depth);
}

Vec3 fog_transmittance_to_light(const Media& media, const Light& light, const Vec3& p) {
  return transmittance_of_depth(vec(fog_optical_depth_to_light(media, light, p)));
}

Vec3 transmittance_to_light(const Media& media, const Light& light, const Vec3& p, int steps, double max_distance, double jitter) {
  return transmittance_of_depth(vec(fog_optical_depth_to_light(media, light, p)) +
                                vec(volumes_optical_depth_to_light(media, light, p, steps, max_distance, jitter)));
}

}  // namespace volgraph::physics
