#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates temporal accumulation's shared maths on a table of inputs — view_uvz
// (view_rays.glsl), froxel_uvw (froxel.glsl), temporal_blend (temporal_blend.glsl) — for
// the test that holds them to their CPU twins (tests/gpu/physics_twins_test.cpp).
#include "include/froxel.glsl"
#include "include/temporal_blend.glsl"

layout(local_size_x = 64) in;

struct Case {
  ViewRays view;
  FroxelGrid grid;
  vec4 point;  // xyz world; w unused
  vec4 blend;  // x current, y history value, z history frames, w alpha
  vec4 valid;  // x: 1 when the history is valid
};
layout(set = 0, binding = 0) readonly buffer Cases { Case cases[]; };
layout(set = 0, binding = 1) writeonly buffer Results { vec4 results[]; };  // three per case

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= cases.length()) return;
  const Case c = cases[i];
  results[3 * i] = vec4(view_uvz(c.view, c.point.xyz), 0.0);
  results[3 * i + 1] = froxel_uvw(c.view, c.grid, c.point.xyz);
  const vec4 blended = temporal_blend(vec4(c.blend.x), vec4(vec3(c.blend.y), c.blend.z), c.valid.x > 0.5, c.blend.w);
  results[3 * i + 2] = vec4(blended.r, blended.a, 0.0, 0.0);
}
