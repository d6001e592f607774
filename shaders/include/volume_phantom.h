// The procedural phantoms of volume_phantom (passes/volume/volume_phantom.cpp): a scalar
// density at a point p of the unit box [0, 1]³ (its centre at 0.5). ONE TEXT FOR BOTH SIDES:
// GLSL includes this file, C++ includes it inside a namespace with GLM's types
// (physics/volume_phantom.h), so the tests know every texel the GPU writes.
//
// Both phantoms are ramps in the distance r from the centre (signed-distance-like): density
// ramp(x) = clamp(0.5 + x / shell, 0, 1) of the signed distance x inside a boundary, so a
// boundary's isosurface of density ρ lies exactly `(0.5 − ρ)·shell` outside it.
#ifndef VOLGRAPH_VOLUME_PHANTOM_H
#define VOLGRAPH_VOLUME_PHANTOM_H

#include "volume_fn.h"

// The variants' codes (VariantDecl::shader_code).
#define VOLUME_PHANTOM_SPHERE 0
#define VOLUME_PHANTOM_SHELLS 1

// The shells' densities, outermost first, and their boundaries as fractions of `radius`.
#define VOLUME_SHELL_OUTER_DENSITY 0.25
#define VOLUME_SHELL_MIDDLE_DENSITY 0.5
#define VOLUME_SHELL_CORE_DENSITY 1.0

// The ramp across a boundary: 0.5 on it, rising inward over `shell` (box fractions).
VOLUME_FN float volume_ramp(float inside_distance, float shell) {
  return clamp(0.5f + inside_distance / max(shell, 1e-6f), 0.0f, 1.0f);
}

// The sphere: ramp(radius − r). Its isosurface of density ρ is the sphere of radius
// volume_sphere_iso_radius(ρ) exactly (where the ramp is not clamped: |0.5 − ρ| < 0.5).
VOLUME_FN float volume_sphere_density(vec3 p, float radius, float shell) {
  return volume_ramp(radius - length(p - vec3(0.5f)), shell);
}
VOLUME_FN float volume_sphere_iso_radius(float iso, float radius, float shell) { return radius + (0.5f - iso) * shell; }

// A band inner ≤ r ≤ outer with ramped edges: the smaller of its two edges' ramps.
VOLUME_FN float volume_band(float r, float inner, float outer, float shell) {
  return min(volume_ramp(r - inner, shell), volume_ramp(outer - r, shell));
}

// Nested shells: the outer one (0.8–1 of radius) of density 0.25, the middle one
// (0.45–0.65) of 0.5 and a core (below 0.25) of 1, empty between them.
VOLUME_FN float volume_shells_density(vec3 p, float radius, float shell) {
  const float r = length(p - vec3(0.5f));
  const float outer = float(VOLUME_SHELL_OUTER_DENSITY) * volume_band(r, 0.8f * radius, radius, shell);
  const float middle = float(VOLUME_SHELL_MIDDLE_DENSITY) * volume_band(r, 0.45f * radius, 0.65f * radius, shell);
  const float core = float(VOLUME_SHELL_CORE_DENSITY) * volume_ramp(0.25f * radius - r, shell);
  return max(max(outer, middle), core);
}

VOLUME_FN float volume_phantom_density(int phantom, vec3 p, float radius, float shell) {
  return phantom == VOLUME_PHANTOM_SHELLS ? volume_shells_density(p, radius, shell) : volume_sphere_density(p, radius, shell);
}

#endif  // VOLGRAPH_VOLUME_PHANTOM_H
