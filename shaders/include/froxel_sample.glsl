// The froxel chain's integrated in-scattering and transmittance from the camera to view
// depth z (m) along the ray through image coordinate uv ([0, 1]², row 0 at the top), read
// trilinearly from scatter_integrate's volumes. Slice k's texel holds the integral to the
// slice's far edge, so depth w (slice coordinate) reads at w − ½/N; in front of the first
// slice's far edge the values ramp linearly from the camera (nothing, full transmittance).
// Shared by froxel_apply (at each pixel's opaque depth) and the translucency passes (at
// each translucent surface's depth).
#ifndef VOLGRAPH_FROXEL_SAMPLE_GLSL
#define VOLGRAPH_FROXEL_SAMPLE_GLSL
#include "fog_frame.glsl"

struct FogAtPixel {
  vec3 in_scatter;
  vec3 transmittance;
};

FogAtPixel froxel_fog_at(FogFrame f, texture3D integrated_scattering, texture3D integrated_transmittance, sampler trilinear,
                         vec2 uv, float z) {
  const float slices = float(f.grid.size.z);
  const float w = froxel_w(f.grid, z);
  const float ramp = clamp(w * slices, 0.0, 1.0);
  const vec3 uvw = vec3(uv, max(w - 0.5 / slices, 0.5 / slices));
  FogAtPixel fog;
  fog.in_scatter = textureLod(sampler3D(integrated_scattering, trilinear), uvw, 0.0).rgb * ramp;
  fog.transmittance = 1.0 - (1.0 - textureLod(sampler3D(integrated_transmittance, trilinear), uvw, 0.0).rgb) * ramp;
  return fog;
}

#endif
