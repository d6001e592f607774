// The in-scattering sum of froxel_scatter and raymarch_fog: CPU twin of
// shaders/include/in_scattering.glsl (change both together), in double. The radiance per
// metre the media at p send toward the camera (DESIGN.md units),
//   S = σs·(Σ_lights p(θ)·E·V·T_media + L_ambient) + emission,
// p(θ) the pass's phase variant (phase.h, chosen by its PHASE_* code), E each light's
// unshadowed delivery (lighting.h), V its visibility (a shadow map's, which the caller
// supplies; 1 without one) and T_media the media's transmittance toward it
// (light_transmittance.h): the global and height fog's in closed form, times the local
// volumes' by a march (none for a light whose V already holds them). The same skips as
// the GLSL: the light loop where σs is zero in every channel (when asked), a light's march
// where it delivers nothing — neither changes S.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "graph/scene/scene.h"
#include "physics/camera.h"
#include "physics/light_transmittance.h"
#include "physics/lighting.h"
#include "physics/media_field.h"
#include "physics/phase.h"
#include "shaders/include/phase_codes.h"

namespace volgraph::physics {

// The phase function of a pass: its variant's code and the dual-lobe HG's other lobe.
struct PhaseChoice {
  int code = PHASE_HG;     // PHASE_* (shaders/include/phase_codes.h)
  double g_back = -0.3;    // PHASE_DUAL_HG: the backward lobe's g (the forward lobe's is the medium's)
  double w_forward = 0.7;  // PHASE_DUAL_HG: the forward lobe's weight
};

// `phase` for a medium of mean cosine g, clamped to ±kHgMaxAbsGForFp16 (where HG's
// forward peak would overflow rgba16f) for every variant that reads it.
template <typename Real>
Real phase_of(const PhaseChoice& phase, Real g, Real cos_theta) {
  g = std::clamp(g, -kHgMaxAbsGForFp16<Real>, kHgMaxAbsGForFp16<Real>);
  switch (phase.code) {
    case PHASE_ISOTROPIC: return phase_isotropic<Real>();
    case PHASE_RAYLEIGH: return phase_rayleigh(cos_theta);
    case PHASE_SCHLICK: return phase_schlick(schlick_k(g), cos_theta);
    case PHASE_DUAL_HG: return phase_dual_hg(g, Real(phase.g_back), Real(phase.w_forward), cos_theta);
    default: return phase_hg(g, cos_theta);
  }
}

// The march through the local volumes toward each light for T_media (transmittance_to_light).
struct LightMarch {
  int steps = 0;              // 0: no march (T_media is the fogs' closed form alone)
  double max_distance = 50;   // m, toward directional lights
  double jitter = 0.5;        // in [0, 1): where inside each step σt is sampled
};

// The shaders' hooks: every light fully visible, each marched (no shadow map).
struct Unshadowed {
  Vec3 visibility(size_t /*light*/, const Vec3& /*p*/) const { return {1, 1, 1}; }
  bool media_shadow_mapped(size_t /*light*/) const { return false; }
};

// S at p for the media sample `m` (its σs, g and emission; σa is not read), `to_camera`
// the unit direction from p toward the camera, `ambient` L_ambient (W/(m²·sr)), `media`
// what the march toward each light samples. `shadows` stands for the including shader's
// light_visibility and media_shadow_mapped: `visibility(light, p)` → Vec3,
// `media_shadow_mapped(light)` → bool.
template <typename Shadows = Unshadowed>
Vec3 in_scattering(const MediaSample& m, const Vec3& p, const Vec3& to_camera, const PhaseChoice& phase,
                   const std::vector<Light>& lights, const Vec3& ambient, const Media& media, const LightMarch& march,
                   bool skip_without_scattering, const Shadows& shadows = {}) {
  const bool scatters = glm::any(glm::greaterThan(vec(m.sigma_s), glm::dvec3(0)));
  if (skip_without_scattering && !scatters) return m.emission;
  glm::dvec3 light = vec(ambient);
  for (size_t i = 0; i < lights.size(); ++i) {
    const LightArriving a = light_arriving(lights[i], p);
    const glm::dvec3 visible = vec(shadows.visibility(i, p)), irradiance = vec(a.irradiance);
    const bool delivers = glm::any(glm::notEqual(irradiance, glm::dvec3(0)));
    if (glm::all(glm::lessThanEqual(visible, glm::dvec3(0))) || !delivers) continue;
    const int steps = shadows.media_shadow_mapped(i) ? 0 : march.steps;
    const glm::dvec3 through = vec(transmittance_to_light(media, lights[i], p, steps, march.max_distance, march.jitter));
    const double phase_value = phase_of(phase, m.g, glm::dot(vec(a.travel), vec(to_camera)));
    light += phase_value * irradiance * (visible * through);
  }
  return to_vec3(vec(m.sigma_s) * light + vec(m.emission));
}

}  // namespace volgraph::physics
