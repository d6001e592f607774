// The scene's participating media at a world-space point (CPU twin of
// shaders/include/media_field.glsl), and their packing into that include's MediaField
// block. Global fog, exponential height fog and local volumes add up, each medium's σs,
// σa and emission scaled by its density there (height fog: e^(−falloff·(y − base));
// a volume: its edge fade times its noise density, physics/noise.h); g is the σs-weighted
// mean. Double precision; the CPU reference evaluates its media through visit().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/camera.h"
#include "shaders/include/media_field.h"

namespace volgraph::physics {

struct MediaSample {
  Vec3 sigma_s{0, 0, 0}, sigma_a{0, 0, 0}, emission{0, 0, 0};
  double g = 0;
  Vec3 sigma_t() const { return to_vec3(vec(sigma_s) + vec(sigma_a)); }
};

// Media summed with their densities as MediaField::sample sums them: each medium's σs,
// σa and emission times its density, g the σs-weighted mean of the media's.
class MediaSum {
 public:
  void add(const Medium& m, double density);
  MediaSample result() const;

 private:
  MediaSample sum_;
  double g_weight_ = 0;
};

// The media with each volume's world-to-local transform computed once.
class MediaField {
 public:
  explicit MediaField(Media media);
  MediaSample sample(const Vec3& p) const;

  // Calls medium_with_density(medium, density) for every medium present at p with its
  // density there (> 0), in the order sample() sums them: the global fog (1), the
  // height fog, then each volume.
  template <typename Visitor>
  void visit(const Vec3& p, Visitor&& medium_with_density) const {
    if (media_.fog) medium_with_density(*media_.fog, 1.0);
    if (media_.height_fog) medium_with_density(media_.height_fog->medium, height_fog_density(p));
    for (size_t i = 0; i < media_.volumes.size(); ++i) {
      const double density = volume_density(i, p);
      if (density > 0) medium_with_density(media_.volumes[i].medium, density);
    }
  }

  double height_fog_density(const Vec3& p) const;
  // Volume `i`'s density at p: 0 outside, else edge fade × noise density, in [0, 1].
  double volume_density(size_t i, const Vec3& p) const;
  // Distance inside volume `i`'s surface at p, in its local units (negative outside).
  double inside_distance(size_t i, const Vec3& p) const;

  const Media& media() const { return media_; }
  const Mat4& world_to_local(size_t i) const { return world_to_local_[i]; }

 private:
  double inside_distance_local(size_t i, const Vec3& local) const;

  Media media_;
  std::vector<Mat4> world_to_local_;
};

constexpr int kMaxMediumVolumes = 8;  // MAX_MEDIUM_VOLUMES in media_field.glsl

// std140 mirror of MediaField in media_field.glsl.
// Each lists its members' offsets (offsets(): passes/plumbing/programs.h).
// The packed media: gpu::MediaField, gpu::MediumVolume, gpu::MediumCoefficients, written once
// for GLSL and C++ (shaders/include/media_field.h).
static_assert(GPU_MAX_MEDIUM_VOLUMES == kMaxMediumVolumes, "shaders/include/media_field.h and physics name one limit");
static_assert(sizeof(gpu::MediaField) == 16 + 2 * 48 + 16 + kMaxMediumVolumes * 160);

// Throws std::logic_error past kMaxMediumVolumes volumes (passes refuse such scenes at validate time: fog_frame.h).
gpu::MediaField pack_media(const Media& media);

}  // namespace volgraph::physics
