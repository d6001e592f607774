// Procedural 3D noise for heterogeneous media: gradient noise (Perlin 2002, "Improving
// Noise": gradients from the 12 cube-edge directions, the quintic fade 6t⁵ − 15t⁴ + 10t³)
// whose lattice gradients come from an integer hash (the PCG hash of Jarzynski & Olano
// 2020, "Hash Functions for GPU Rendering", JCGT 9(3)) instead of a permutation table,
// summed over octaves as fractional Brownian motion (Quilez, "fBm": lacunarity 2, gain
// 0.5), and remapped to a density multiplier in [0, 1] with a coverage (Schneider & Vos
// 2015, "The real-time volumetric cloudscapes of Horizon Zero Dawn", the remap of the
// base shape by coverage). CPU twin of shaders/include/noise.glsl: change both together.
// The hash is exact in 32-bit unsigned arithmetic, so the GPU and a float twin pick the
// same gradients and agree to rounding; templates on the real type (float: what the GPU
// computes; double: the reference).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace volgraph::physics {

// Octaves a volume's noise may have (the config checks 1 … kMaxNoiseOctaves).
constexpr int kMaxNoiseOctaves = 8;

// Lattice coordinates are clamped to ±this many cells so that the cell index fits an
// int32 on both sides (a volume that large has lost float's fractional precision anyway).
template <typename Real>
constexpr Real kNoiseLatticeLimit = Real(1 << 30);

// Octave k's lattice is offset by k times this (in its own cells), so that the lattice
// points where every octave vanishes do not line up (dyadic: exact in float).
template <typename Real>
constexpr Real kOctaveOffset[3] = {Real(0.3125), Real(0.5625), Real(0.8125)};

// PCG hash (Jarzynski & Olano 2020, §2: one LCG step, then PCG's RXS-M-XS output).
inline uint32_t pcg_hash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Perlin 2002's gradient at a lattice point, one of the 12 edge directions of a cube
// (±1, ±1, 0), (±1, 0, ±1), (0, ±1, ±1), dotted with the offset (fx, fy, fz) from it.
template <typename Real>
Real gradient_dot(uint32_t hash, Real fx, Real fy, Real fz) {
  const uint32_t i = hash % 12u;
  const uint32_t pair = i / 4u;  // 0: xy, 1: xz, 2: yz
  const Real u = pair == 2u ? fy : fx;
  const Real v = pair == 0u ? fy : fz;
  return ((i & 1u) == 0u ? u : -u) + ((i & 2u) == 0u ? v : -v);
}

// Perlin 2002's fade: 6t⁵ − 15t⁴ + 10t³ (C² across cells).
template <typename Real>
Real noise_fade(Real t) {
  return t * t * t * (t * (t * Real(6) - Real(15)) + Real(10));
}

template <typename Real>
Real noise_lerp(Real a, Real b, Real t) {
  return a + t * (b - a);
}

// Gradient noise at p (lattice units), in about [−1, 1], 0 at every lattice point.
template <typename Real>
Real gradient_noise(Real px, Real py, Real pz, uint32_t octave) {
  const Real lx = std::clamp(px, -kNoiseLatticeLimit<Real>, kNoiseLatticeLimit<Real>);
  const Real ly = std::clamp(py, -kNoiseLatticeLimit<Real>, kNoiseLatticeLimit<Real>);
  const Real lz = std::clamp(pz, -kNoiseLatticeLimit<Real>, kNoiseLatticeLimit<Real>);
  const Real cx = std::floor(lx), cy = std::floor(ly), cz = std::floor(lz);
  const Real fx = lx - cx, fy = ly - cy, fz = lz - cz;
  const int32_t x = int32_t(cx), y = int32_t(cy), z = int32_t(cz);
  // Each corner's hash is pcg(x + pcg(y + pcg(z + octave))), the inner hashes shared
  // between corners (corner k: bit 0 x, bit 1 y, bit 2 z).
  uint32_t hash_z[2], hash_yz[4];
  for (int32_t d = 0; d < 2; ++d) hash_z[d] = pcg_hash(uint32_t(z + d) + octave);
  for (int32_t k = 0; k < 4; ++k) hash_yz[k] = pcg_hash(uint32_t(y + (k & 1)) + hash_z[k >> 1]);
  Real corner[8];
  for (int32_t k = 0; k < 8; ++k) {
    const int32_t dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
    corner[k] = gradient_dot(pcg_hash(uint32_t(x + dx) + hash_yz[k >> 1]), fx - Real(dx), fy - Real(dy), fz - Real(dz));
  }
  const Real u = noise_fade(fx), v = noise_fade(fy), w = noise_fade(fz);
  const Real x00 = noise_lerp(corner[0], corner[1], u), x10 = noise_lerp(corner[2], corner[3], u);
  const Real x01 = noise_lerp(corner[4], corner[5], u), x11 = noise_lerp(corner[6], corner[7], u);
  return noise_lerp(noise_lerp(x00, x10, v), noise_lerp(x01, x11, v), w);
}

// fBm (Quilez): Σ_{k<octaves} 0.5^k · noise(2^k·p + k·offset) / Σ_{k<octaves} 0.5^k, p in
// units of the largest feature (lattice cells of octave 0); about [−1, 1] at any count.
template <typename Real>
Real fbm(Real px, Real py, Real pz, int octaves) {
  Real sum = 0, amplitude = 1, total = 0, frequency = 1;
  for (int k = 0; k < octaves; ++k) {
    const Real shift = Real(k);
    sum += amplitude * gradient_noise(px * frequency + shift * kOctaveOffset<Real>[0], py * frequency + shift * kOctaveOffset<Real>[1],
                                      pz * frequency + shift * kOctaveOffset<Real>[2], uint32_t(k));
    total += amplitude;
    amplitude *= Real(0.5);
    frequency *= Real(2);
  }
  return total > Real(0) ? sum / total : Real(0);
}

// The density multiplier of noise at p: the fBm mapped to [0, 1] as n = 0.5 + fbm
// (clamped), then remapped by coverage c ∈ (0, 1] (Schneider & Vos 2015):
// clamp((n − (1 − c)) / c, 0, 1) — c = 1 keeps n, smaller c empties the thin parts and
// leaves denser puffs.
template <typename Real>
Real noise_density(Real px, Real py, Real pz, int octaves, Real coverage) {
  const Real n = std::clamp(Real(0.5) + fbm(px, py, pz, octaves), Real(0), Real(1));
  return std::clamp((n - (Real(1) - coverage)) / coverage, Real(0), Real(1));
}

}  // namespace volgraph::physics
