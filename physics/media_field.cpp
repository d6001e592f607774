#include "physics/media_field.h"

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

void add_medium(MediaSample& s, double& g_weight, const Medium& m, double density) {
  const Vec3 sigma_s = scaled(m.sigma_s, density);
  s.sigma_s = add(s.sigma_s, sigma_s);
  s.sigma_a = add(s.sigma_a, scaled(m.sigma_a, density));
  s.emission = add(s.emission, scaled(m.emission, density));
  const double weight = sigma_s[0] + sigma_s[1] + sigma_s[2];
  s.g += m.g * weight;
  g_weight += weight;
}

GpuMediumCoefficients gpu_coefficients(const Medium& m) {
  GpuMediumCoefficients c{};
  for (size_t i = 0; i < 3; ++i) {
    c.sigma_s_g[i] = float(m.sigma_s[i]);
    c.sigma_a[i] = float(m.sigma_a[i]);
    c.emission[i] = float(m.emission[i]);
  }
  c.sigma_s_g[3] = float(m.g);
  return c;
}

}  // namespace

MediaField::MediaField(Media media) : media_(std::move(media)) {
  for (const MediumVolume& v : media_.volumes) world_to_local_.push_back(inverse_affine(model_matrix(v.transform)));
}

double MediaField::inside_distance(size_t i, const Vec3& p) const {
  return inside_distance_local(i, transform_point(world_to_local_[i], p));
}

double MediaField::inside_distance_local(size_t i, const Vec3& local) const {
  const MediumVolume& v = media_.volumes[i];
  switch (v.shape) {
    case Shape::box: {
      double d = 1e300;
      for (size_t k = 0; k < 3; ++k) d = std::min(d, 0.5 * v.size[k] - std::abs(local[k]));
      return d;
    }
    case Shape::sphere: return v.size[0] - std::sqrt(dot(local, local));
    default: {
      const Vec3 radii{std::max(v.size[0], 1e-12), std::max(v.size[1], 1e-12), std::max(v.size[2], 1e-12)};
      const Vec3 q{local[0] / radii[0], local[1] / radii[1], local[2] / radii[2]};
      return (1 - std::sqrt(dot(q, q))) * std::min({radii[0], radii[1], radii[2]});
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
  const double fade = noise.edge_fade > 0 ? std::clamp(d / noise.edge_fade, 0.0, 1.0) : 1.0;
  if (noise.octaves == 0 || fade == 0) return fade;
  const Vec3 q = scaled(local, 1 / noise.scale);
  return fade * noise_density(q[0], q[1], q[2], noise.octaves, noise.coverage);
}

MediaSample MediaField::sample(const Vec3& p) const {
  MediaSample s;
  double g_weight = 0;
  visit(p, [&](const Medium& m, double density) { add_medium(s, g_weight, m, density); });
  s.g = g_weight > 0 ? s.g / g_weight : 0;
  return s;
}

GpuMediaField pack_media(const Media& media) {
  if (media.volumes.size() > size_t(kMaxMediumVolumes)) {
    throw std::logic_error("at most " + std::to_string(kMaxMediumVolumes) + " medium volumes");
  }
  GpuMediaField f{};
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
    GpuMediumVolume& g = f.volumes[i];
    to_floats(inverse_affine(model_matrix(v.transform)), g.world_to_local);
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
