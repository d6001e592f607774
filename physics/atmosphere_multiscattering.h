// Hillaire 2020 (§5.5, "A Scalable and Production Ready Sky and Atmosphere Rendering
// Technique"): the contribution of every scattering order past the first, approximated
// as isotropic and independent of the view, Ψ_ms(r, mu_s) for a sun of unit illuminance.
// From a point at radius r lit by the sun at zenith cosine mu_s, over `directions`²
// directions uniform on the sphere, each ray marched to its boundary in `steps` midpoint
// steps with Hillaire's energy-conserving integration ((S − S·T)/σt a step):
//   L_2nd = ∫_Ω L_f(x, ω) p_u dω, L_f the light scattered once toward x (isotropic phase
//           p_u = 1/4π, the sun's transmittance, the ground's Lambertian bounce)   (eq. 5, 6)
//   f_ms  = ∫_Ω ∫ σs T p_u dt dω, the fraction transferred to the next order          (eq. 7, 8)
//   Ψ_ms  = L_2nd / (1 − f_ms)                                                          (eq. 9, 10)
// CPU twin of shaders/include/atmosphere_multiscattering.glsl (which reads the sun's
// transmittance from the transmittance LUT; this computes it exactly) — change both together.
#pragma once

#include "graph/scene/scene.h"

namespace volgraph::physics {

struct MultiscatteringSettings {
  int directions_per_axis = 8;  // Hillaire 2020: 64 directions
  int steps = 20;               // Hillaire 2020: 20 samples a ray
};

// L_2nd and f_ms (per channel) at (r, mu_s).
struct MultiscatteringTerms {
  Vec3 second_order{0, 0, 0};
  Vec3 transfer{0, 0, 0};
};
MultiscatteringTerms multiscattering_terms(const Atmosphere& atmosphere, double r, double mu_s, MultiscatteringSettings settings = {});

// Ψ_ms = L_2nd / (1 − f_ms) (f_ms < 1 for any physical atmosphere: each order loses energy).
Vec3 multiscattering(const Atmosphere& atmosphere, double r, double mu_s, MultiscatteringSettings settings = {});

}  // namespace volgraph::physics
