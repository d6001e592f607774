// Phase functions normalised over the sphere; cos_theta between the light's direction of
// travel and the scattered direction (forward: 1). CPU twin: physics/phase.h —
// change both together; the formulas and their precision notes are documented there.
#ifndef VOLGRAPH_PHASE_GLSL
#define VOLGRAPH_PHASE_GLSL

const float INV_FOUR_PI = 0.0795774715459476679;
const float HG_MAX_ABS_G_FOR_FP16 = 0.998;
const float SCHLICK_MAX_K = 0.9999;

float phase_isotropic() { return INV_FOUR_PI; }

float phase_rayleigh(float cos_theta) { return 0.75 * INV_FOUR_PI * (1.0 + cos_theta * cos_theta); }

// 1 + g² − 2g cosθ as a sum of non-negative terms: (1 − g)² + 2g(1 − cosθ) for g ≥ 0,
// (1 + g)² − 2g(1 + cosθ) for g < 0 (physics/phase.h).
float phase_hg_base(float g, float cos_theta) {
  return g >= 0.0 ? (1.0 - g) * (1.0 - g) + 2.0 * g * (1.0 - cos_theta) : (1.0 + g) * (1.0 + g) - 2.0 * g * (1.0 + cos_theta);
}

// Henyey–Greenstein 1941, its denominator's base by phase_hg_base.
float phase_hg(float g, float cos_theta) {
  const float one_minus_g = 1.0 - g;
  const float base = phase_hg_base(g, cos_theta);
  return INV_FOUR_PI * one_minus_g * (1.0 + g) / max(base * sqrt(base), 1e-30);
}

// Cornette & Shanks 1992 (Applied Optics 31, eq. 4), as Bruneton 2017's MiePhaseFunction.
float phase_cornette_shanks(float g, float cos_theta) {
  const float one_minus_g = 1.0 - g;
  const float base = phase_hg_base(g, cos_theta);
  const float denominator = max((2.0 + g * g) * base * sqrt(base), 1e-30);
  return 1.5 * INV_FOUR_PI * one_minus_g * (1.0 + g) * (1.0 + cos_theta * cos_theta) / denominator;
}

// Schlick (Blasi, Le Saëc, Schlick 1993): k ≈ 1.55g − 0.55g³, clamped inside (−1, 1).
float schlick_k(float g) { return clamp(1.55 * g - 0.55 * g * g * g, -SCHLICK_MAX_K, SCHLICK_MAX_K); }

float phase_schlick(float k, float cos_theta) {
  const float base = k >= 0.0 ? (1.0 - k) + k * (1.0 - cos_theta) : (1.0 + k) - k * (1.0 + cos_theta);
  return INV_FOUR_PI * (1.0 - k) * (1.0 + k) / max(base * base, 1e-30);
}

// Two HG lobes mixed, the two-term Henyey–Greenstein function (Kattawar 1975, "A
// three-parameter analytic phase function for multiple scattering calculations").
float phase_dual_hg(float g_forward, float g_backward, float w_forward, float cos_theta) {
  return w_forward * phase_hg(g_forward, cos_theta) + (1.0 - w_forward) * phase_hg(g_backward, cos_theta);
}

#endif
