#version 450
#extension GL_GOOGLE_include_directive : require
// Evaluates media_average.glsl (and shape_interval.glsl through it) over a table of ray
// segments, for the test that holds them to their CPU twins (tests/gpu/physics_twins_test.cpp).
#include "include/media_average.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform Field { MediaField media; } field;
// Three per segment: xyz origin, w t0; xyz ray, w t1; x jitter.
layout(set = 0, binding = 1) readonly buffer Segments { vec4 segments[]; };
layout(set = 0, binding = 2) writeonly buffer Results { vec4 results[]; };  // seven per segment

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (3 * i >= segments.length()) return;
  const vec4 start = segments[3 * i], heading = segments[3 * i + 1];
  const vec3 o = start.xyz, ray = heading.xyz;
  const float t0 = start.w, t1 = heading.w, jitter = segments[3 * i + 2].x;
  vec2 chords[4];
  vec4 means = vec4(0.0);
  for (int v = 0; v < 4; ++v) {
    chords[v] = volume_interval(field.media.volumes[v], o, ray);
    means[v] = volume_mean_density(field.media.volumes[v], o, ray, t0, t1, jitter);
  }
  results[7 * i] = vec4(chords[0], chords[1]);
  results[7 * i + 1] = vec4(chords[2], chords[3]);
  results[7 * i + 2] = means;
  results[7 * i + 3] = vec4(height_fog_mean_density(field.media, o, ray, t0, t1), 0.0, 0.0, 0.0);
  const MediaSample m = average_media(field.media, o, ray, t0, t1, jitter);
  results[7 * i + 4] = vec4(m.sigma_s, m.g);
  results[7 * i + 5] = vec4(m.sigma_a, 0.0);
  results[7 * i + 6] = vec4(m.emission, 0.0);
}
