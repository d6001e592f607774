// The scene's participating media at a world-space point (CPU twin of
// shaders/include/media_field.glsl), and their packing into that include's MediaField
// block. Global fog, exponential height fog and local volumes with an edge fade add up;
// g is the σs-weighted mean. Noise density is not sampled yet.
#pragma once

#include <vector>

#include "graph/scene/scene.h"
#include "passes/shading/camera.h"

namespace volgraph::shading {

struct MediaSample {
  Vec3 sigma_s{0, 0, 0}, sigma_a{0, 0, 0}, emission{0, 0, 0};
  double g = 0;
  Vec3 sigma_t() const { return add(sigma_s, sigma_a); }
};

// The media with each volume's world-to-local transform computed once.
class MediaField {
 public:
  explicit MediaField(const Media& media);
  MediaSample sample(const Vec3& p) const;
  // Distance inside volume `i`'s surface at p, in its local units (negative outside).
  double inside_distance(size_t i, const Vec3& p) const;

 private:
  const Media& media_;
  std::vector<Mat4> world_to_local_;
};

constexpr int kMaxMediumVolumes = 8;  // MAX_MEDIUM_VOLUMES in media_field.glsl

// std140 mirror of MediaField in media_field.glsl.
struct GpuMediumCoefficients {
  float sigma_s_g[4], sigma_a[4], emission[4];
};
struct GpuMediumVolume {
  float world_to_local[16];
  float size_shape[4];
  float fade[4];
  GpuMediumCoefficients medium;
};
struct GpuMediaField {
  int32_t counts[4];
  GpuMediumCoefficients fog, height_fog;
  float height[4];
  GpuMediumVolume volumes[kMaxMediumVolumes];
};
static_assert(sizeof(GpuMediaField) == 16 + 2 * 48 + 16 + kMaxMediumVolumes * 144);

// Throws DeviceError (unsupported) past kMaxMediumVolumes volumes.
GpuMediaField pack_media(const Media& media);

}  // namespace volgraph::shading
