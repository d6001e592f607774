// The media's transmittance from a point toward a light (CPU twin of
// shaders/include/light_transmittance.glsl — change both together), e^(−τ) with τ:
// - the global fog and the height fog in closed form, always: toward a point or spot
//   light σt·d of the global fog plus the height fog's closed-form optical depth along the
//   segment (physics/media.h); toward a directional light the height fog's to infinity
//   (infinite when the light travels level or upward) and no global fog — a directional
//   light's E is what reaches a point through the global fog (DESIGN.md; the reference's
//   SceneMedia::optical_depth_to_infinity, which this follows);
// - plus the local volumes, each σt × its chord on the segment to the light (`max_distance`
//   m toward a directional one) × its mean density there (physics/media_average.h): exact
//   for a volume without edge fade or noise, the mean of `steps` points stratified over the
//   chord otherwise.
#pragma once

#include "graph/scene/scene.h"
#include "physics/camera.h"
#include "physics/media_field.h"

namespace volgraph::physics {

// How far the march toward `light` from `p` goes (m).
double light_march_length(const Light& light, const Vec3& p, double max_distance);

// ∫σt over `length` m from p along unit `direction`, by `steps` equal steps sampled at
// (k + jitter)·Δ.
Vec3 optical_depth_along(const MediaField& field, const Vec3& p, const Vec3& direction, double length, int steps, double jitter);

// The media a march sees: the local volumes alone (the fogs are in closed form).
Media local_volumes(const Media& media);

// The closed-form part of τ: the global fog and the height fog from p toward `light`.
Vec3 fog_optical_depth_to_light(const Media& media, const Light& light, const Vec3& p);

// The local volumes' part of τ toward `light` from p: chords and mean densities as above,
// `steps` (≤ 0: none) stratified samples per chord, each `jitter` (in [0, 1)) into its stratum.
Vec3 volumes_optical_depth_to_light(const Media& media, const Light& light, const Vec3& p, int steps, double max_distance,
                                    double jitter);

// e^(−τ) of the closed-form part alone (what the scene pass dims surfaces by).
Vec3 fog_transmittance_to_light(const Media& media, const Light& light, const Vec3& p);

// e^(−τ) of the two parts together.
Vec3 transmittance_to_light(const Media& media, const Light& light, const Vec3& p, int steps, double max_distance, double jitter);

}  // namespace volgraph::physics
