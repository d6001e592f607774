#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates noise.glsl and media_field.glsl at a table of points, for the test that holds
// them to their CPU twins (tests/gpu/physics_twins_test.cpp).
#include "include/media_field.glsl"
#include "include/noise.glsl"

layout(local_size_x = 64) in;

struct Point {
  vec4 position;  // xyz: world position for the media, lattice position for the noise; w: octaves
  vec4 noise;     // x coverage, y octave of the single gradient noise
};
layout(set = 0, binding = 0) uniform Field { MediaField media; } field;
layout(set = 0, binding = 1) readonly buffer Points { Point points[]; };
layout(set = 0, binding = 2) writeonly buffer Results { vec4 results[]; };  // four per point

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= points.length()) return;
  const Point q = points[i];
  const vec3 p = q.position.xyz;
  const int octaves = int(q.position.w);
  results[4 * i] = vec4(gradient_noise(p, uint(q.noise.y)), fbm(p, octaves), noise_density(p, octaves, q.noise.x), 0.0);
  const MediaSample s = sample_media(field.media, p);
  results[4 * i + 1] = vec4(s.sigma_s, s.g);
  results[4 * i + 2] = vec4(s.sigma_a, 0.0);
  results[4 * i + 3] = vec4(s.emission, 0.0);
}
