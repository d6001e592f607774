// A tabulated phase function's parameterisation (cloud_phase_table's texture, read by
// cloud_march with CLOUD_PHASE_TABLE): texel i of N holds p(θ_i) per channel at
// θ_i = π u_i², u_i = (i + ½)/N, dense near the forward diffraction peak of cloud droplets;
// a lookup reads the two texels around u = sqrt(θ/π) and mixes them linearly (clamped at
// the ends). The texture is rgba32float, which WebGPU cannot filter: the mix is done here,
// so the GPU and the C++ twin (physics/cloud_phase_table.h) interpolate alike.
//
// ONE TEXT FOR BOTH SIDES, as cloud_lighting.h: GLSL includes this file, C++ includes it
// inside a namespace with GLM's types.
#ifndef VOLGRAPH_CLOUD_PHASE_TABLE_H
#define VOLGRAPH_CLOUD_PHASE_TABLE_H

#include "cloud_fn.h"

#define CLOUD_PHASE_TABLE_PI 3.14159265358979323846f

// θ of texel i of n: u_i = (i + ½)/n, θ_i = π u_i².
CLOUD_FN float cloud_phase_table_angle(int i, int n) {
  const float u = (float(i) + 0.5f) / float(n);
  return CLOUD_PHASE_TABLE_PI * u * u;
}

// cos θ's position in a table of n texels, texel i's centre at i: u n − ½, u = sqrt(θ/π),
// clamped to [0, n − 1].
CLOUD_FN float cloud_phase_table_position(float cos_theta, int n) {
  const float theta = acos(clamp(cos_theta, -1.0f, 1.0f));
  return clamp(sqrt(theta / CLOUD_PHASE_TABLE_PI) * float(n) - 0.5f, 0.0f, float(n - 1));
}

// The texels around position x: the lower floor(x), the upper the next (the last at the end).
CLOUD_FN int cloud_phase_table_lower(float x) { return int(floor(x)); }
CLOUD_FN int cloud_phase_table_upper(float x, int n) { return min(int(floor(x)) + 1, n - 1); }

// The linear mix of the two texels' p at position x.
CLOUD_FN vec3 cloud_phase_table_mix(vec3 lower, vec3 upper, float x) { return mix(lower, upper, x - floor(x)); }

#endif
