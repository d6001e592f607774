// The cloud noises of Schneider & Vos 2015 ("The real-time volumetric cloudscapes of
// Horizon Zero Dawn", Advances in Real-Time Rendering; Schneider 2017, "Nubis"): tileable
// gradient (Perlin 2002) and cellular (Worley 1996, F1) noise on a lattice that wraps
// every `period` cells, their fractional Brownian sums, the Perlin-Worley remap, and the
// texels of the three textures the cloud_noise pass writes.
//
// ONE TEXT FOR BOTH SIDES: GLSL includes this file, and C++ includes it inside a namespace
// with GLM's types (physics/cloud_noise.h), so the CPU twin is the shader's own code. Keep
// it to what both languages read the same: no swizzles, float literals with an `f`, integer
// lattice coordinates never below −period (the wrap uses %, undefined for negatives in GLSL).
#ifndef VOLGRAPH_CLOUD_NOISE_H
#define VOLGRAPH_CLOUD_NOISE_H

#include "cloud_fn.h"

// Periods of the shape texture's channels (cells across the tile): Perlin-Worley at 4,
// then Worley sums at 4, 8 and 16; the detail texture's Worley sums at 2, 4 and 8; the
// curl texture's potential at 4 (Schneider & Vos 2015: low-frequency shape, higher-frequency
// Worley octaves for the detail).
#define CLOUD_SHAPE_PERIOD 4
#define CLOUD_DETAIL_PERIOD 2
#define CLOUD_CURL_PERIOD 4
#define CLOUD_PERLIN_OCTAVES 4

// PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", §2).
CLOUD_FN uint cloud_hash(uint v) {
  const uint state = v * 747796405u + 2891336453u;
  const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// The hash of lattice point `cell` on a lattice that repeats every `period` cells.
CLOUD_FN uint cloud_cell_hash(ivec3 cell, int period, uint seed) {
  const ivec3 wrapped = (cell + ivec3(period)) % period;
  return cloud_hash(uint(wrapped.x) + cloud_hash(uint(wrapped.y) + cloud_hash(uint(wrapped.z) + seed)));
}

// Perlin 2002's gradient (one of the 12 cube-edge directions) dotted with offset f.
CLOUD_FN float cloud_gradient_dot(uint hash, vec3 f) {
  const uint i = hash % 12u;
  const uint pair = i / 4u;  // 0: xy, 1: xz, 2: yz
  const float u = pair == 2u ? f.y : f.x;
  const float v = pair == 0u ? f.y : f.z;
  return ((i & 1u) == 0u ? u : -u) + ((i & 2u) == 0u ? v : -v);
}

// Perlin 2002's quintic fade 6t⁵ − 15t⁴ + 10t³.
CLOUD_FN float cloud_fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// Gradient noise at p (in cells, p ≥ 0), about [−1, 1], repeating every `period` cells.
CLOUD_FN float cloud_perlin(vec3 p, int period, uint seed) {
  const vec3 base = floor(p);
  const ivec3 cell = ivec3(base);
  const vec3 f = p - base;
  float corners[8];
  for (int k = 0; k < 8; ++k) {
    const ivec3 corner = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    corners[k] = cloud_gradient_dot(cloud_cell_hash(cell + corner, period, seed), f - vec3(corner));
  }
  const float u = cloud_fade(f.x), v = cloud_fade(f.y), w = cloud_fade(f.z);
  const float x00 = mix(corners[0], corners[1], u), x10 = mix(corners[2], corners[3], u);
  const float x01 = mix(corners[4], corners[5], u), x11 = mix(corners[6], corners[7], u);
  return mix(mix(x00, x10, v), mix(x01, x11, v), w);
}

// Worley 1996's F1 (the distance to the nearest feature point, one jittered point a cell),
// inverted to 1 − F1 and clamped to [0, 1]: bright at the points, as the clouds' billows.
CLOUD_FN float cloud_worley(vec3 p, int period, uint seed) {
  const vec3 base = floor(p);
  const ivec3 cell = ivec3(base);
  const vec3 f = p - base;
  float nearest = 3.0f;  // squared; the farthest a neighbour's point can be is below √3·2
  for (int z = -1; z <= 1; ++z) {
    for (int y = -1; y <= 1; ++y) {
      for (int x = -1; x <= 1; ++x) {
        const ivec3 offset = ivec3(x, y, z);
        const uint h = cloud_cell_hash(cell + offset, period, seed);
        const vec3 jitter = vec3(float(h & 1023u), float((h >> 10u) & 1023u), float((h >> 20u) & 1023u)) * (1.0f / 1024.0f);
        const vec3 d = vec3(offset) + jitter - f;
        nearest = min(nearest, dot(d, d));
      }
    }
  }
  return 1.0f - clamp(sqrt(nearest), 0.0f, 1.0f);
}

// Gradient noise summed over octaves (lacunarity 2, gain 1/2), mapped to [0, 1].
CLOUD_FN float cloud_perlin_fbm(vec3 uvw, int period, int octaves, uint seed) {
  float sum = 0.0f, amplitude = 0.5f, total = 0.0f;
  int octave_period = period;
  for (int k = 0; k < octaves; ++k) {
    sum += amplitude * cloud_perlin(uvw * float(octave_period), octave_period, seed + uint(k));
    total += amplitude;
    amplitude *= 0.5f;
    octave_period *= 2;
  }
  return clamp(0.5f + 0.5f * sum / total, 0.0f, 1.0f);
}

// Three Worley octaves, 0.625 / 0.25 / 0.125 (Schneider & Vos 2015's weights), in [0, 1].
CLOUD_FN float cloud_worley_fbm(vec3 uvw, int period, uint seed) {
  return 0.625f * cloud_worley(uvw * float(period), period, seed) + 0.25f * cloud_worley(uvw * float(2 * period), 2 * period, seed + 1u) +
         0.125f * cloud_worley(uvw * float(4 * period), 4 * period, seed + 2u);
}

// Schneider & Vos 2015's Perlin-Worley: the gradient noise dilated by the cellular noise,
// remap(perlin, −(1 − worley), 1, 0, 1): billowy where Worley is bright, connected as Perlin.
CLOUD_FN float cloud_perlin_worley(float perlin, float worley) {
  return clamp((perlin + (1.0f - worley)) / (2.0f - worley), 0.0f, 1.0f);
}

// The shape texture's texel at uvw (texel centres in [0, 1)): r Perlin-Worley, g b a Worley
// sums at increasing frequencies.
CLOUD_FN vec4 cloud_shape_texel(vec3 uvw, uint seed) {
  const float perlin = cloud_perlin_fbm(uvw, CLOUD_SHAPE_PERIOD, CLOUD_PERLIN_OCTAVES, seed);
  const float worley = cloud_worley_fbm(uvw, CLOUD_SHAPE_PERIOD, seed + 16u);
  return vec4(cloud_perlin_worley(perlin, worley), worley, cloud_worley_fbm(uvw, 2 * CLOUD_SHAPE_PERIOD, seed + 32u),
              cloud_worley_fbm(uvw, 4 * CLOUD_SHAPE_PERIOD, seed + 48u));
}

// The detail texture's texel: r g b Worley sums at increasing frequencies, a 1.
CLOUD_FN vec4 cloud_detail_texel(vec3 uvw, uint seed) {
  return vec4(cloud_worley_fbm(uvw, CLOUD_DETAIL_PERIOD, seed + 64u), cloud_worley_fbm(uvw, 2 * CLOUD_DETAIL_PERIOD, seed + 80u),
              cloud_worley_fbm(uvw, 4 * CLOUD_DETAIL_PERIOD, seed + 96u), 1.0f);
}

// The curl texture's texel: the 2D curl (∂ψ/∂y, −∂ψ/∂x) of a gradient-noise potential ψ
// (Bridson et al. 2007, "Curl-noise for procedural fluid flow"), by central differences
// `delta` apart in uv, encoded as 0.5 + 0.5 · curl / CLOUD_CURL_SCALE (clamped) in r and g.
#define CLOUD_CURL_SCALE 8.0f
CLOUD_FN vec4 cloud_curl_texel(vec2 uv, float delta, uint seed) {
  const float right = cloud_perlin_fbm(vec3(uv.x + delta, uv.y, 0.0f), CLOUD_CURL_PERIOD, 2, seed + 112u);
  const float left = cloud_perlin_fbm(vec3(uv.x - delta + 1.0f, uv.y, 0.0f), CLOUD_CURL_PERIOD, 2, seed + 112u);
  const float up = cloud_perlin_fbm(vec3(uv.x, uv.y + delta, 0.0f), CLOUD_CURL_PERIOD, 2, seed + 112u);
  const float down = cloud_perlin_fbm(vec3(uv.x, uv.y - delta + 1.0f, 0.0f), CLOUD_CURL_PERIOD, 2, seed + 112u);
  const vec2 curl = vec2(up - down, left - right) / (2.0f * delta);
  return vec4(clamp(vec2(0.5f) + 0.5f * curl / CLOUD_CURL_SCALE, vec2(0.0f), vec2(1.0f)), 0.0f, 1.0f);
}

#endif
