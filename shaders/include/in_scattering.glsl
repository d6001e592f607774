// The in-scattering sum, written once for froxel_scatter (per froxel) and raymarch_fog (per
// sample of its march): the radiance per metre the media at p send toward the camera,
//   S = σs·(Σ_lights p(θ)·E·V·T_media + L_ambient) + emission   (DESIGN.md units),
// p(θ) the pass's phase function (its variant: a PHASE_* code of phase_codes.h, with the
// dual-lobe HG's backward lobe), E what the light delivers unshadowed (lighting.glsl), V the
// including shader's `light_visibility(int light, vec3 p)` (a float; or a vec3 that also holds
// the local volumes' transmittance toward that light, from an opacity shadow map) and T_media
// the media's transmittance toward the light (light_transmittance.glsl): the global and
// height fog's in closed form always, times the local volumes' by a march of `steps` (none
// with 0 steps, nor for a light where the including shader's `bool media_shadow_mapped(int
// light)` says light_visibility holds it). The including shader defines both hooks, and its frame
// block `frame` (`uniform Frame { FogFrame f; } frame`, fog_frame.glsl: the lights, L_ambient
// and the media the march samples), before it includes this file: read there rather than
// passed in, as lavapipe copies a LightList or MediaField argument at every call (the march
// was 15–20 % slower so). CPU twin: physics/in_scattering.h — change both together.
//
// What is skipped (the result does not change): the light loop where σs is zero in every
// channel, when the caller asks (`skip_without_scattering`: froxel_scatter's `skip_empty`,
// always for raymarch_fog) — S is then the emission alone; a light's march where it
// delivers nothing (V ≤ 0 in every channel, or E = 0).
// The clamps of what is stored (rgba16f's range) stay with the callers.
#ifndef VOLGRAPH_IN_SCATTERING_GLSL
#define VOLGRAPH_IN_SCATTERING_GLSL
#include "fog_frame.glsl"
#include "light_transmittance.glsl"
#include "phase.glsl"
#include "phase_codes.h"

// The phase function of a pass: its variant's code and the dual-lobe HG's other lobe.
struct PhaseChoice {
  int code;         // PHASE_* (phase_codes.h)
  float g_back;     // PHASE_DUAL_HG: the backward lobe's g (the forward lobe's is the medium's)
  float w_forward;  // PHASE_DUAL_HG: the forward lobe's weight
};

// `phase` for a medium of mean cosine g, clamped to ±HG_MAX_ABS_G_FOR_FP16 (where HG's
// forward peak would overflow rgba16f) for every variant that reads it.
float phase_of(PhaseChoice phase, float g, float cos_theta) {
  g = clamp(g, -HG_MAX_ABS_G_FOR_FP16, HG_MAX_ABS_G_FOR_FP16);
  switch (phase.code) {
    case PHASE_ISOTROPIC: return phase_isotropic();
    case PHASE_RAYLEIGH: return phase_rayleigh(cos_theta);
    case PHASE_SCHLICK: return phase_schlick(schlick_k(g), cos_theta);
    case PHASE_DUAL_HG: return phase_dual_hg(g, phase.g_back, phase.w_forward, cos_theta);
    default: return phase_hg(g, cos_theta);
  }
}

// The march through the local volumes toward each light for T_media (transmittance_to_light).
struct LightMarch {
  int steps;           // 0: no march (T_media is the fogs' closed form alone)
  float max_distance;  // m, toward directional lights
  float jitter;        // in [0, 1): where inside each step σt is sampled
};

// S at p for the media sample `m` (its σs, g and emission; σa is not read), `to_camera`
// the unit direction from p toward the camera; frame.f's lights, ambient radiance (W/(m²·sr))
// and media.
vec3 in_scattering(MediaSample m, vec3 p, vec3 to_camera, PhaseChoice phase, LightMarch march, bool skip_without_scattering) {
  if (skip_without_scattering && !any(greaterThan(m.sigma_s, vec3(0.0)))) return m.emission;
  vec3 light = frame.f.ambient.rgb;
  const Fogs fogs = fogs_of(frame.f.media.counts, frame.f.media.fog, frame.f.media.height_fog, frame.f.media.height);
  for (int i = 0; i < frame.f.light_list.counts.x; ++i) {
    vec3 travel;
    const vec3 e = light_arriving(frame.f.light_list.lights[i], p, travel);
    const vec3 visible = vec3(light_visibility(i, p));
    if (all(lessThanEqual(visible, vec3(0.0))) || all(equal(e, vec3(0.0)))) continue;
    const int steps = media_shadow_mapped(i) ? 0 : march.steps;  // a map's light: T_media is in light_visibility
    const vec3 through = transmittance_to_light(fogs, frame.f.media, frame.f.light_list.lights[i], p, -travel, steps,
                                                march.max_distance, march.jitter);
    light += phase_of(phase, m.g, dot(travel, to_camera)) * e * (visible * through);
  }
  return m.sigma_s * light + m.emission;
}

#endif
