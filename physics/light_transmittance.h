// Volumetric shadows: the transmittance of the media from a point toward a light by a
// march of equal steps (CPU twin of shaders/include/light_transmittance.glsl — change
// both together): e^(−Σ_k σt(p + (k + jitter)·Δ·ω)·Δ), Δ the march length / steps.
// Directional lights march `max_distance` m with the global fog left out (their E is
// what reaches a point through it, DESIGN.md); point and spot lights march to the light.
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

// The media a march toward `light` sees: a directional light's without the global fog.
Media media_toward_light(const Media& media, const Light& light);

// `steps` ≤ 0: no volumetric shadow (1). `jitter` in [0, 1): where inside each step σt
// is sampled.
Vec3 transmittance_to_light(const Media& media, const Light& light, const Vec3& p, int steps, double max_distance, double jitter);

}  // namespace volgraph::physics
