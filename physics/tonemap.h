// CPU twin of shaders/include/tonemap.glsl: the same curves, for the reference
// renderer and the tests. Change both together.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace volgraph::physics {

enum class ToneMap : int { none = 0, aces = 1, reinhard = 2 };

using Rgb = std::array<double, 3>;

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": x(ax + b) / (x(cx + d) + e), clamped.
inline double tone_map_aces(double x) {
  const double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// Reinhard et al. 2002, eq. 3: L / (1 + L), per channel.
inline double tone_map_reinhard(double x) { return x / (1.0 + x); }

inline Rgb tone_map(const Rgb& radiance, double exposure_ev, ToneMap op) {
  Rgb out;
  for (size_t c = 0; c < 3; ++c) {
    const double x = std::max(radiance[c], 0.0) * std::exp2(exposure_ev);
    out[c] = op == ToneMap::aces ? tone_map_aces(x) : op == ToneMap::reinhard ? tone_map_reinhard(x) : x;
  }
  return out;
}

}  // namespace volgraph::physics
