// A planet's atmosphere as every atmosphere pass holds it (`uniform Atmosphere { AtmosphereParameters a; } atmosphere;`;
// physics::pack_atmosphere fills it from physics::Atmosphere), one text for GLSL and C++ (gpu_struct.h).
#ifndef VOLGRAPH_ATMOSPHERE_PARAMETERS_H
#define VOLGRAPH_ATMOSPHERE_PARAMETERS_H
#include "gpu_struct.h"

GPU_BEGIN
// exp_term · e^(exp_scale · h) + linear_term · h + constant_term (Bruneton 2017, DensityProfileLayer).
GPU_STRUCT(AtmosphereLayer) {
  vec4 terms;  // exp_term, exp_scale, linear_term, constant_term
};

GPU_STRUCT(AtmosphereProfile) {
  AtmosphereLayer lower, upper;
  vec4 width;  // x: the lower layer's width (m)
};

GPU_STRUCT(AtmosphereParameters) {
  vec4 radii;                  // bottom, top (m), sun angular radius (rad), Mie g
  vec4 rayleigh_scattering;    // 1/m
  vec4 mie_scattering;         // 1/m; w: the Mie phase (MIE_PHASE_*, physics::kMiePhase*)
  vec4 mie_extinction;         // 1/m
  vec4 absorption_extinction;  // 1/m
  vec4 ground_albedo;
  AtmosphereProfile rayleigh_density, mie_density, absorption_density;
};
GPU_END

#endif  // VOLGRAPH_ATMOSPHERE_PARAMETERS_H
