// The cloud layer's density at a point, from the noise texels (Schneider & Vos 2015, "The
// real-time volumetric cloudscapes of Horizon Zero Dawn", Advances in Real-Time Rendering;
// Schneider 2016, GPU Pro 7 "Real-Time Volumetric Cloudscapes", §4.3): the height fraction
// in the layer, the cloud types' height gradients, the shape's base density under the
// coverage, the detail's erosion at the edges, and the extinction of a density.
//
// ONE TEXT FOR BOTH SIDES, as shaders/include/cloud_noise.h: GLSL includes this file, and
// C++ includes it inside a namespace with GLM's types (physics/cloud_density.h). No
// swizzles, float literals with an `f`, no arrays of structs; texel-level maths only (the
// textures are sampled by the caller).
#ifndef VOLGRAPH_CLOUD_DENSITY_H
#define VOLGRAPH_CLOUD_DENSITY_H

#include "cloud_fn.h"

// Schneider & Vos 2015's remap: v's place in [lo, hi] carried to [new_lo, new_hi], not
// clamped (hi ≠ lo).
CLOUD_FN float cloud_remap(float v, float lo, float hi, float new_lo, float new_hi) {
  return new_lo + (v - lo) * (new_hi - new_lo) / (hi - lo);
}

// Where `altitude` sits in the layer: 0 at its bottom, 1 at its top, clamped (GPU Pro 7
// §4.3.2, the height fraction); a layer thinner than a millimetre counts as one millimetre.
CLOUD_FN float cloud_height_fraction(float altitude, float bottom, float top) {
  return clamp((altitude - bottom) / max(top - bottom, 1e-3f), 0.0f, 1.0f);
}

// Schneider & Vos 2015's height gradients ("cloud types" slides; GPU Pro 7 §4.3.2): each
// type a rise smoothstep(x, y, h) minus a fall smoothstep(z, w, h), 0 < x < y ≤ z < w ≤ 1,
// so 0 at h = 0 and at h = 1. `type` 0 stratus (low, thin), 0.5 cumulus, 1 cumulonimbus
// (tall); between them the four heights blend linearly, which keeps their order.
CLOUD_FN float cloud_height_gradient(float h, float type) {
  const vec4 stratus = vec4(0.02f, 0.05f, 0.09f, 0.11f);
  const vec4 cumulus = vec4(0.02f, 0.2f, 0.48f, 0.625f);
  const vec4 cumulonimbus = vec4(0.01f, 0.0625f, 0.78f, 1.0f);
  const float t = clamp(type, 0.0f, 1.0f);
  const float w_stratus = 1.0f - clamp(2.0f * t, 0.0f, 1.0f);
  const float w_cumulonimbus = clamp(2.0f * t - 1.0f, 0.0f, 1.0f);
  const float w_cumulus = 1.0f - w_stratus - w_cumulonimbus;
  const vec4 g = w_stratus * stratus + w_cumulus * cumulus + w_cumulonimbus * cumulonimbus;
  const float x = clamp(h, 0.0f, 1.0f);
  return max(smoothstep(g.x, g.y, x) - smoothstep(g.z, g.w, x), 0.0f);
}

// The base density from the shape texel (r Perlin-Worley, g b a Worley sums) at height
// fraction h (GPU Pro 7 §4.3.3, Schneider & Vos 2015's "shape" slides): the Worley FBM
// 0.625 g + 0.25 b + 0.125 a dilates r, remap(r, fbm − 1, 1, 0, 1); times the height
// gradient; then the coverage, remap(base, 1 − coverage, 1, 0, 1) × coverage. In [0, 1];
// coverage 0 gives 0, coverage 1 the base as it is.
CLOUD_FN float cloud_base_density(vec4 shape, float h, float coverage, float type) {
  const float fbm = clamp(0.625f * shape.y + 0.25f * shape.z + 0.125f * shape.w, 0.0f, 1.0f);
  const float dilated = clamp(cloud_remap(clamp(shape.x, 0.0f, 1.0f), fbm - 1.0f, 1.0f, 0.0f, 1.0f), 0.0f, 1.0f);
  const float base = dilated * cloud_height_gradient(h, type);
  const float c = clamp(coverage, 0.0f, 1.0f);
  // The remap's range 1 − (1 − c) is c: kept above zero so coverage 0 reads 0, not 0/0.
  const float covered = clamp(cloud_remap(base, 1.0f - max(c, 1e-6f), 1.0f, 0.0f, 1.0f), 0.0f, 1.0f);
  return covered * c;
}

// The base density eroded at its edges by the detail texel (r g b Worley sums) at height
// fraction h (GPU Pro 7 §4.3.4, Schneider & Vos 2015's "erosion" slides): the detail FBM
// 0.625 r + 0.25 g + 0.125 b, inverted toward the bottom (wispy there, billowy above a
// tenth of the layer), then remap(base, fbm × 0.35, 1, 0, 1). In [0, base]: the remap
// lowers every base ≤ 1 and thin edges go to 0 first.
CLOUD_FN float cloud_eroded_density(float base, vec4 detail, float h) {
  const float fbm = clamp(0.625f * detail.x + 0.25f * detail.y + 0.125f * detail.z, 0.0f, 1.0f);
  const float modifier = mix(1.0f - fbm, fbm, clamp(10.0f * h, 0.0f, 1.0f));
  const float b = clamp(base, 0.0f, 1.0f);
  return clamp(cloud_remap(b, 0.35f * modifier, 1.0f, 0.0f, 1.0f), 0.0f, b);
}

// The extinction coefficient σt (1/m) of a density: the layer's `extinction` (σt at density
// 1) times the density (Schneider & Vos 2015, Beer's law slides: density scales σt).
CLOUD_FN float cloud_extinction(float extinction, float density) { return extinction * density; }

// The scattering coefficient σs (1/m): the cloud scatters without absorbing (albedo 1,
// docs/clouds.md), so σs = σt.
CLOUD_FN float cloud_scattering(float extinction, float density) { return cloud_extinction(extinction, density); }

#endif
