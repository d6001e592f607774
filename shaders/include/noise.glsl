// Procedural 3D noise for heterogeneous media: gradient noise (Perlin 2002, "Improving
// Noise": the 12 cube-edge gradients, the quintic fade) with lattice gradients from the
// PCG integer hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering"), fBm over
// octaves (Quilez: lacunarity 2, gain 0.5), remapped to a density in [0, 1] by a coverage
// (Schneider & Vos 2015). CPU twin, with the definitions spelt out:
// physics/noise.h — change both together. The hash is exact uint arithmetic.
#ifndef VOLGRAPH_NOISE_GLSL
#define VOLGRAPH_NOISE_GLSL

const float NOISE_LATTICE_LIMIT = 1073741824.0;  // 2^30 cells: the cell index fits an int
const vec3 NOISE_OCTAVE_OFFSET = vec3(0.3125, 0.5625, 0.8125);

// PCG hash (Jarzynski & Olano 2020, §2).
uint pcg_hash(uint v) {
  const uint state = v * 747796405u + 2891336453u;
  const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Perlin 2002's gradient (one of the 12 cube-edge directions) dotted with the offset f.
float gradient_dot(uint hash, vec3 f) {
  const uint i = hash % 12u;
  const uint pair = i / 4u;  // 0: xy, 1: xz, 2: yz
  const float u = pair == 2u ? f.y : f.x;
  const float v = pair == 0u ? f.y : f.z;
  return ((i & 1u) == 0u ? u : -u) + ((i & 2u) == 0u ? v : -v);
}

// 6t⁵ − 15t⁴ + 10t³ per component.
vec3 noise_fade(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float noise_lerp(float a, float b, float t) { return a + t * (b - a); }

// Gradient noise at p (lattice units), in about [−1, 1].
float gradient_noise(vec3 p, uint octave) {
  const vec3 l = clamp(p, vec3(-NOISE_LATTICE_LIMIT), vec3(NOISE_LATTICE_LIMIT));
  const vec3 c = floor(l);
  const vec3 f = l - c;
  const ivec3 cell = ivec3(c);
  // Corner k (bit 0 x, bit 1 y, bit 2 z) hashes as pcg(x + pcg(y + pcg(z + octave))).
  uint hash_z[2], hash_yz[4];
  for (int d = 0; d < 2; ++d) hash_z[d] = pcg_hash(uint(cell.z + d) + octave);
  for (int k = 0; k < 4; ++k) hash_yz[k] = pcg_hash(uint(cell.y + (k & 1)) + hash_z[k >> 1]);
  float corner[8];
  for (int k = 0; k < 8; ++k) {
    const ivec3 d = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    corner[k] = gradient_dot(pcg_hash(uint(cell.x + d.x) + hash_yz[k >> 1]), f - vec3(d));
  }
  const vec3 w = noise_fade(f);
  const float x00 = noise_lerp(corner[0], corner[1], w.x), x10 = noise_lerp(corner[2], corner[3], w.x);
  const float x01 = noise_lerp(corner[4], corner[5], w.x), x11 = noise_lerp(corner[6], corner[7], w.x);
  return noise_lerp(noise_lerp(x00, x10, w.y), noise_lerp(x01, x11, w.y), w.z);
}

// Σ_{k<octaves} 0.5^k · noise(2^k·p + k·offset) / Σ 0.5^k, p in octave 0's cells.
float fbm(vec3 p, int octaves) {
  float sum = 0.0, amplitude = 1.0, total = 0.0, frequency = 1.0;
  for (int k = 0; k < octaves; ++k) {
    const float shift = float(k);
    sum += amplitude * gradient_noise(vec3(p.x * frequency + shift * NOISE_OCTAVE_OFFSET.x, p.y * frequency + shift * NOISE_OCTAVE_OFFSET.y,
                                           p.z * frequency + shift * NOISE_OCTAVE_OFFSET.z), uint(k));
    total += amplitude;
    amplitude *= 0.5;
    frequency *= 2.0;
  }
  return total > 0.0 ? sum / total : 0.0;
}

// The density multiplier in [0, 1]: n = clamp(0.5 + fbm), then clamp((n − (1 − c)) / c).
float noise_density(vec3 p, int octaves, float coverage) {
  const float n = clamp(0.5 + fbm(p, octaves), 0.0, 1.0);
  return clamp((n - (1.0 - coverage)) / coverage, 0.0, 1.0);
}

#endif
