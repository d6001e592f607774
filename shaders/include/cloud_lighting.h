// The cloud layer's lighting at a sample (Schneider & Vos 2015; RTR4 14.4.2): the
// dual-lobe Henyey–Greenstein phase, Wrenninge et al. 2013's multiple-scattering octaves
// (RTR4 eq. 14.18) — with that phase or a tabulated one (cloud_phase_table.h) — and Schneider &
// Vos's optional, non-physical powder term.
//
// ONE TEXT FOR BOTH SIDES, as shaders/include/cloud_density.h: GLSL includes this file, and
// C++ includes it inside a namespace with GLM's types (physics/cloud_lighting.h). The HG
// lobe is phase.glsl's phase_hg on the GPU; phase.glsl itself cannot be compiled as C++
// (unsuffixed double literals in max(float, 1e-30) do not deduce with GLM, and its
// functions are not inline), so the C++ twin binds phase_hg to physics/phase.h's
// phase_hg<float>, phase.glsl's documented twin (same formula, same base).
#ifndef VOLGRAPH_CLOUD_LIGHTING_H
#define VOLGRAPH_CLOUD_LIGHTING_H

#include "cloud_fn.h"

#ifndef __cplusplus
#include "phase.glsl"
#endif

// The octave count's ceiling: the march's `octaves` parameter stays within it.
#define CLOUD_MAX_OCTAVES 8

// Two HG lobes mixed (Schneider & Vos 2015, "Silver lining" slides; RTR4 14.4.2):
// mix(HG(g_forward), HG(g_back), back_weight). Normalised over the sphere for any weight in [0, 1].
CLOUD_FN float cloud_phase(float cos_theta, float g_forward, float g_back, float back_weight) {
  const float w = clamp(back_weight, 0.0f, 1.0f);
  return mix(phase_hg(g_forward, cos_theta), phase_hg(g_back, cos_theta), w);
}

// The octaves' scales as both sums take them: b and c clamped to [0, 1], a to [0, b]
// (Wrenninge's energy condition a ≤ b), the count to [1, CLOUD_MAX_OCTAVES].
struct CloudOctaveScales {
  float a, b, c;
  int count;
};
CLOUD_FN CloudOctaveScales cloud_octave_scales(int octaves, float a, float b, float c) {
  const float bb = clamp(b, 0.0f, 1.0f);
  const CloudOctaveScales k = {min(clamp(a, 0.0f, 1.0f), bb), bb, clamp(c, 0.0f, 1.0f), clamp(octaves, 1, CLOUD_MAX_OCTAVES)};  // GLSL 4.2's initializer list
  return k;
}

// Wrenninge et al. 2013's multiple-scattering approximation (RTR4 eq. 14.18): the sum over
// i < octaves of b^i σs p(θ, c^i g) T(a^i τ), T(x) = exp(−x), τ the optical depth toward
// the sun. octaves = 1 is single scattering σs p(θ, g) T(τ). a ≤ b is enforced (a above b
// is read as b: Wrenninge's energy condition); a, b, c are clamped to [0, 1], octaves to
// [1, CLOUD_MAX_OCTAVES]. Radiance per metre per unit sun illuminance.
CLOUD_FN float cloud_octaves(float sigma_s, float tau, float cos_theta, float g_forward, float g_back, float back_weight,
                             int octaves, float a, float b, float c) {
  const CloudOctaveScales k = cloud_octave_scales(octaves, a, b, c);
  const float t = max(tau, 0.0f);
  const float s = max(sigma_s, 0.0f);
  float sum = 0.0f;
  float weight = 1.0f, depth = 1.0f, spread = 1.0f;  // b^i, a^i, c^i
  for (int i = 0; i < k.count; ++i) {
    sum += weight * s * cloud_phase(cos_theta, spread * g_forward, spread * g_back, back_weight) * exp(-depth * t);
    weight *= k.b;
    depth *= k.a;
    spread *= k.c;
  }
  return sum;
}

// Wrenninge's octaves (RTR4 eq. 14.18) with a tabulated phase (cloud_phase_table.h): `phase` is
// the table's p at θ per channel; octave i's phase is mix(1/4π, p, c^i), whose mean cosine
// is exactly c^i g (the isotropic part has none), as the HG octaves' p(θ, c^i g). The same
// clamps as cloud_octaves. Radiance per metre per unit sun illuminance, per channel.
CLOUD_FN vec3 cloud_octaves_tabulated(float sigma_s, float tau, vec3 phase, int octaves, float a, float b, float c) {
  const CloudOctaveScales k = cloud_octave_scales(octaves, a, b, c);
  const float t = max(tau, 0.0f);
  const float s = max(sigma_s, 0.0f);
  vec3 sum = vec3(0.0f);
  float weight = 1.0f, depth = 1.0f, spread = 1.0f;  // b^i, a^i, c^i
  for (int i = 0; i < k.count; ++i) {
    sum += weight * s * mix(vec3(phase_isotropic()), phase, spread) * exp(-depth * t);
    weight *= k.b;
    depth *= k.a;
    spread *= k.c;
  }
  return sum;
}

// Schneider & Vos 2015's "powder" darkening of edges that face the sun: 2 (1 − exp(−2τ))
// multiplies the sun's term. NOT PHYSICAL: it is an art term (it reaches 2 inside thick
// cloud, so it breaks the energy bound); off by default, `on` 0 leaves the factor 1.
CLOUD_FN float cloud_powder(float tau, float on) {
  return mix(1.0f, 2.0f * (1.0f - exp(-2.0f * max(tau, 0.0f))), clamp(on, 0.0f, 1.0f));
}

#endif
