#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates in_scattering.glsl on a table of cases, for the test that holds it to its CPU
// twin physics/in_scattering.h (tests/gpu/physics_twins_test.cpp). The frame block holds
// the lights, the ambient radiance and the media; each case its point, media sample, phase
// variant, march and the shadow map's hooks over light 0.
#include "include/fog_frame.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Frame { FogFrame f; } frame;

struct Case {
  vec4 position;   // xyz: p; w: the phase code
  vec4 to_camera;  // xyz: unit direction toward the camera; w: 1 skips the light loop where σs is zero
  vec4 sigma_s;    // rgb σs; a: g
  vec4 emission;   // rgb
  vec4 phase;      // x g_back, y w_forward
  vec4 march;      // x steps, y max_distance, z jitter
  vec4 shadow;     // x: light 0's visibility (× 1, 0.5, 0.25 per channel); y: 1 when it also holds light 0's media transmittance
};
layout(set = 0, binding = 1) readonly buffer Cases { Case cases[]; };
layout(set = 0, binding = 2) writeonly buffer Results { vec4 results[]; };  // one per case

// The hooks read the case being evaluated (one per invocation).
vec4 current_shadow;
vec3 light_visibility(int light, vec3 p) {
  return light == 0 ? current_shadow.x * vec3(1.0, 0.5, 0.25) : vec3(1.0);
}
bool media_shadow_mapped(int light) { return light == 0 && current_shadow.y > 0.5; }

#include "include/in_scattering.glsl"

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  const Case c = cases[i];
  current_shadow = c.shadow;
  const MediaSample m = MediaSample(c.sigma_s.rgb, vec3(0.0), c.emission.rgb, c.sigma_s.a);
  const vec3 s = in_scattering(m, c.position.xyz, c.to_camera.xyz, PhaseChoice(int(c.position.w), c.phase.x, c.phase.y),
                               LightMarch(int(c.march.x), c.march.y, c.march.z), c.to_camera.w > 0.5);
  results[i] = vec4(s, 0.0);
}
