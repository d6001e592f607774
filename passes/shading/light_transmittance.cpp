#include "passes/shading/light_transmittance.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "passes/shading/lighting.h"
#include "passes/shading/media.h"
#include "passes/shading/media_field.h"

namespace volgraph::shading {

double light_march_length(const Light& light, const Vec3& p, double max_distance) {
  if (light.type == LightType::directional) return max_distance;
  const Vec3 d = sub(light.position, p);
  return std::sqrt(dot(d, d));
}

Vec3 transmittance_to_light(const Media& media, const Light& light, const Vec3& p, int steps, double max_distance, double jitter) {
  if (steps <= 0) return {1, 1, 1};
  Media marched = media;
  if (light.type == LightType::directional) marched.fog.reset();
  const MediaField field(std::move(marched));
  const Vec3 to_light = scaled(light_arriving(light, p).travel, -1);
  const double step_length = light_march_length(light, p, max_distance) / steps;
  Vec3 optical_depth{0, 0, 0};
  for (int k = 0; k < steps; ++k) {
    const MediaSample s = field.sample(add(p, scaled(to_light, (k + jitter) * step_length)));
    optical_depth = add(optical_depth, scaled(s.sigma_t(), step_length));
  }
  Vec3 t;
  for (size_t c = 0; c < 3; ++c) t[c] = std::exp(-std::min(optical_depth[c], kMaxExponent<double>));
  return t;
}

}  // namespace volgraph::shading
