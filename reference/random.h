// The Monte Carlo references' random numbers (reference/atmosphere_reference.cpp,
// reference/cloud_path_tracer.cpp): deterministic across libraries and runs.
#pragma once

#include <cstdint>
#include <random>

namespace volgraph::reference {

// splitmix64 (Steele, Lea, Flood 2014): decorrelates consecutive seeds.
inline uint64_t splitmix64(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Uniform doubles in [0, 1): an mt19937_64's 53 high bits (std's distributions differ
// between libraries).
class Random {
 public:
  explicit Random(uint64_t seed) : engine_(seed) {}
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace volgraph::reference
