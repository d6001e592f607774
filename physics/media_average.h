// The media averaged over a stretch of a ray (CPU twin of
// shaders/include/media_average.glsl): froxel_voxelize's value of a froxel, the mean of
// MediaField::sample over the points origin + t·ray, t ∈ [t0, t1], of the froxel's centre
// ray (t: view depth, `ray` of forward component 1). Each medium's density is averaged:
// - the global fog: 1;
// - the height fog: the exact mean of e^(−falloff·(y − base)), its optical depth in
//   closed form (physics/media.h) over the length;
// - a volume without edge fade or noise: the exact fraction of [t0, t1] inside its shape
//   (physics/shape_interval.h);
// - a volume with an edge fade or noise: that fraction times the mean density of
//   kMediaSubSamples points stratified over the part inside, each at `jitter` (within ±½)
//   of a stratum from the stratum's centre — the mean over jitters is the exact average.
// Double precision.
#pragma once

#include <optional>

#include "physics/media_field.h"
#include "physics/shape_interval.h"

namespace volgraph::physics {

constexpr int kMediaSubSamples = 4;  // MEDIA_SUB_SAMPLES in media_average.glsl

// The points origin + t·ray for t ∈ [t0, t1], t0 < t1 (ray of any length).
struct RaySegment {
  Vec3 origin{0, 0, 0}, ray{0, 0, 1};
  double t0 = 0, t1 = 1;
};

// Where the ray origin + t·ray runs inside volume `i` of the field (none for a volume of
// size 0: it has no inside).
std::optional<RayInterval> volume_interval(const MediaField& field, size_t i, const Vec3& origin, const Vec3& ray);

// The mean height-fog density over the segment, at most MediaField's largest density
// e^kMaxExponent (the closed form overflows float past it).
double height_fog_mean_density(const HeightFog& fog, const RaySegment& s);

// The mean density of volume `i` over the segment, with `samples` stratified points inside
// it where the volume has an edge fade or noise.
double volume_mean_density(const MediaField& field, size_t i, const RaySegment& s, double jitter, int samples = kMediaSubSamples);

// Every medium's σs, σa and emission averaged over the segment; g the σs-weighted mean.
MediaSample average_media(const MediaField& field, const RaySegment& s, double jitter);

}  // namespace volgraph::physics
