#include "physics/media_field.h"

#include <cstring>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "physics/media.h"
#include "physics/noise.h"

namespace volgraph::physics {
namespace {

int shape_code(Shape shape) {
  switch (shape) {
    case Shape::box: return 1;
    case Shape::sphere: return 2;
    case Shape::ellipsoid: return 3;
    default: return 0;
  }
}

gpu::MediumCoefficients gpu_coefficients(const Medium& m) {
  gpu::MediumCoefficients c{};
  for (size_t i = 0; i < 3; ++i) {
    c.sigma_s_g[i] = float(m.sigma_s[i]);
    c.sigma_a[i] = float(m.sigma_a[i]);
    c.emission[i] = float(m.emission[i]);
  }
  c.sigma_s_g[3] = float(m.g);
  return c;
}

}  // namespace

void MediaSum::add(const Medium& m, double density) {
  const glm::dvec3 sigma_s = vec(m.sigma_s) * density;
  sum_.sigma_s = to_vec3(vec(sum_.sigma_s) + sigma_s);
  sum_.sigma_a = to_vec3(vec(sum_.sigma_a) + vec(m.sigma_a) * density);
  sum_.emission = to_vec3(vec(sum_.emission) + vec(m.emission) * density);
  const double weight = sigma_s.x + sigma_s.y + sigma_s.z;
  sum_.g += m.g * weight;
  g_weight_ += weight;
}

MediaSample MediaSum::result() const {
  MediaSample s = sum_;
  s.g = g_weight_ > 0 ? s.g / g_weight_ : 0;
  return s;
}

MediaField::MediaField(Media media) : media_(std::move(media)) {
  for (const MediumVolume& v : media_.volumes) world_to_local_.push_back(inverse_affine(model_matrix(v.transform)));
}

double MediaField::inside_distance(size_t i, const Vec3& p) const {
  return inside_distance_local(i, transform_point(world_to_local_[i], p));
}

double MediaField::inside_distance_local(size_t i, const Vec3& local_point) const {
  const MediumVolume& v = media_.volumes[i];
  const glm::dvec3 local = vec(local_point), size = vec(v.size);
  switch (v.shape) {
    case Shape::box: {
      const glm::dvec3 d = 0.5 * size - glm::abs(local);
      return glm::min(glm::min(d.x, d.y), d.z);
    }
    case Shape::sphere: return size.x - glm::length(local);
    default: {
      const glm::dvec3 radii = glm::max(size, 1e-12);
      return (1 - glm::length(local / radii)) * glm::min(glm::min(radii.x, radii.y), radii.z);
    }
  }
}

double MediaField::height_fog_density(const Vec3& p) const {
  const HeightFog& h = *media_.height_fog;
  return std::exp(std::min(-h.falloff * (p[1] - h.base_height), kMaxExponent<double>));
}

double MediaField::volume_density(size_t i, const Vec3& p) const {
  const Vec3 local = transform_point(world_to_local_[i], p);
  const double d = inside_distance_local(i, local);
  if (d < 0) return 0;
  const Noise& noise = media_.volumes[i].noise;
  const double fade = noise.edge_fade > 0 ? glm::clamp(d / noise.edge_fade, 0.0, 1.0) : 1.0;
  if (noise.octaves == 0 || fade == 0) return fade;
  const glm::dvec3 q = vec(local) * (1 / noise.scale);
  return fade * noise_density(q.x, q.y, q.z, noise.octaves, noise.coverage);
}

MediaSample MediaField::sample(const Vec3& p) const {
  MediaSum sum;
  visit(p, [&](const Medium& m, double density) { sum.add(m, density); });
  return sum.result();
}

gpu::MediaField pack_media(const Media& media) {
  if (media.volumes.size() > size_t(kMaxMediumVolumes)) {
    throw std::logic_error("at most " + std::to_string(kMaxMediumVolumes) + " medium volumes");
  }
  gpu::MediaField f{};
  f.counts[0] = int32_t(media.volumes.size());
  f.counts[1] = media.fog ? 1 : 0;
  f.counts[2] = media.height_fog ? 1 : 0;
  if (media.fog) f.fog = gpu_coefficients(*media.fog);
  if (media.height_fog) {
    f.height_fog = gpu_coefficients(media.height_fog->medium);
    f.height[0] = float(media.height_fog->base_height);
    f.height[1] = float(media.height_fog->falloff);
  }
  for (size_t i = 0; i < media.volumes.size(); ++i) {
    const MediumVolume& v = media.volumes[i];
    gpu::MediumVolume& g = f.volumes[i];
    float world_to_local[16];
    to_floats(inverse_affine(model_matrix(v.transform)), world_to_local);
    std::memcpy(&g.world_to_local, world_to_local, sizeof(world_to_local));
    for (size_t k = 0; k < 3; ++k) g.size_shape[k] = float(v.size[k]);
    g.size_shape[3] = float(shape_code(v.shape));
    g.fade[0] = float(v.noise.edge_fade);
    g.noise[0] = float(v.noise.octaves);
    g.noise[1] = float(1 / v.noise.scale);
    g.noise[2] = float(v.noise.coverage);
    g.medium = gpu_coefficients(v.medium);
  }
  return f;
}

}  // namespace volgraph::physics
