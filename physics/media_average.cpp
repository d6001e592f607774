#include "physics/media_average.h"

#include <algorithm>
#include <cmath>

#include "physics/media.h"

namespace volgraph::physics {
namespace {

Vec3 point_at(const RaySegment& s, double t) { return to_vec3(vec(s.origin) + t * vec(s.ray)); }

bool uniform(const MediumVolume& v) { return v.noise.edge_fade <= 0 && v.noise.octaves == 0; }

}  // namespace

std::optional<RayInterval> volume_interval(const MediaField& field, size_t i, const Vec3& origin, const Vec3& ray) {
  const glm::dvec3 scale = vec(unit_shape_scale(field.media().volumes[i]));
  if (glm::min(glm::min(scale.x, scale.y), scale.z) <= 0) return std::nullopt;
  const Mat4& to_local = field.world_to_local(i);
  const glm::dvec3 o = vec(transform_point(to_local, origin)) / scale;
  const glm::dvec3 d = glm::dmat3(to_local) * vec(ray) / scale;
  return unit_shape_interval(field.media().volumes[i].shape, to_vec3(o), to_vec3(d));
}

double height_fog_mean_density(const HeightFog& fog, const RaySegment& s) {
  const double length = std::max(s.t1 - s.t0, 1e-30);  // media_average.glsl's guard: the density at t0
  const double start_y = s.origin[1] + s.t0 * s.ray[1];
  const double depth = height_fog_optical_depth(1.0, fog.falloff, fog.base_height, start_y, s.ray[1], length);
  return std::min(depth / length, std::exp(kMaxExponent<double>));  // MediaField's largest density
}

double volume_mean_density(const MediaField& field, size_t i, const RaySegment& s, double jitter, int samples) {
  const std::optional<RayInterval> chord = volume_interval(field, i, s.origin, s.ray);
  if (!chord) return 0;
  const double a = std::max(s.t0, chord->enter), b = std::min(s.t1, chord->exit);
  if (b <= a) return 0;
  const double inside = (b - a) / (s.t1 - s.t0);
  if (uniform(field.media().volumes[i])) return inside;
  double sum = 0;
  for (int k = 0; k < samples; ++k) {
    sum += field.volume_density(i, point_at(s, a + (b - a) * (k + 0.5 + jitter) / samples));
  }
  return inside * sum / samples;
}

MediaSample average_media(const MediaField& field, const RaySegment& s, double jitter) {
  const Media& media = field.media();
  MediaSum sum;
  if (media.fog) sum.add(*media.fog, 1.0);
  if (media.height_fog) sum.add(media.height_fog->medium, height_fog_mean_density(*media.height_fog, s));
  for (size_t i = 0; i < media.volumes.size(); ++i) {
    const double density = volume_mean_density(field, i, s, jitter);
    if (density > 0) sum.add(media.volumes[i].medium, density);
  }
  return sum.result();
}

}  // namespace volgraph::physics
