// Aerial perspective at a point the camera sees (Hillaire 2020 §5.4): the air's
// in-scattering S (for a sun of unit illuminance) and transmittance T from the camera to
// it, read trilinearly from atmosphere_aerial_perspective's volumes at its pixel and its
// distance along the ray (slice k's texel holds the air to (k + ½) slices; in front of it
// the values ramp from the camera's). Whatever the camera sees through the air becomes
// L·T + S·E. The volumes' frame (AerialLookup) is the one the aerial-perspective pass
// wrote for this frame. CPU twin: physics/atmosphere_lut.h aerial_perspective_slice.
#ifndef VOLGRAPH_ATMOSPHERE_AERIAL_LOOKUP_GLSL
#define VOLGRAPH_ATMOSPHERE_AERIAL_LOOKUP_GLSL

#include "view_rays.glsl"

#include "aerial_lookup.h"  // struct AerialLookup

struct AerialAtPoint {
  vec3 in_scatter;     // radiance added (the sun's E included)
  vec3 transmittance;  // what passes of the radiance behind
};

// `uv`: the point's texture coordinate across the frame (u right, v down); `t`: its
// distance from the camera (m).
AerialAtPoint aerial_perspective_at(AerialLookup f, texture3D aerial_scattering, texture3D aerial_transmittance, sampler trilinear,
                                    vec2 uv, float t) {
  const float half_slice = 0.5 / f.volume.y;
  const float w = max(t, 0.0) / f.volume.x;
  const float ramp = clamp(w / half_slice, 0.0, 1.0);
  const vec3 uvw = vec3(uv, clamp(w, half_slice, 1.0 - half_slice));
  AerialAtPoint air;
  air.in_scatter = textureLod(sampler3D(aerial_scattering, trilinear), uvw, 0.0).rgb * f.sun.rgb * ramp;
  air.transmittance = 1.0 - (1.0 - textureLod(sampler3D(aerial_transmittance, trilinear), uvw, 0.0).rgb) * ramp;
  return air;
}

#endif
