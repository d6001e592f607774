#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates shaders/include/translucency.glsl on a table of inputs, for the test that holds
// it to physics/translucency.h (tests/gpu/physics_twins_test.cpp).
#include "include/translucency.glsl"

layout(local_size_x = 64) in;

struct Case {
  vec4 ray;    // xyz: to_incident (unit), w: eta; the normal is +y
  vec4 slab;   // x: F0, y: cos θ, z: a transmittance colour, w: its distance (m)
};
layout(set = 0, binding = 0) readonly buffer Cases { Case cases[]; };
layout(set = 0, binding = 1) writeonly buffer Results { vec4 results[]; };  // two per case

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  const Case c = cases[i];
  vec3 t;
  const bool refracted = refract_bec(c.ray.xyz, vec3(0.0, 1.0, 0.0), c.ray.w, t);
  results[2 * i] = vec4(t, refracted ? 1.0 : 0.0);
  const float sigma_t = sigma_t_from_color(vec3(c.slab.z), c.slab.w).x;
  results[2 * i + 1] = vec4(fresnel_schlick(c.slab.x, c.slab.y), sigma_t, slab_transmittance(vec3(sigma_t), c.slab.w, c.slab.y).x,
                            fresnel_f0(1.0, 1.0 / c.ray.w));
}
