// The CPU twin of shaders/include/cloud_shadow_lookup.glsl for the tests of cloud_shadow_map's
// readers: the map's τ read back as a linear-clamp sampler reads it, and the uv where the
// sun's ray from a world point meets the map's plane.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "graph/execute/executor.h"
#include "graph/scene/scene.h"
#include "shaders/include/cloud_shadow_view.h"

namespace volgraph::testing {

// τ (r of the read-back map) at (u, v), texel centres at (i + ½)/size, bilinear, clamped.
inline double cloud_shadow_tau_at(const Texels& t, double u, double v) {
  const double x = u * t.width - 0.5, y = v * t.height - 0.5;
  const int i0 = std::clamp(int(std::floor(x)), 0, int(t.width) - 1), j0 = std::clamp(int(std::floor(y)), 0, int(t.height) - 1);
  const int i1 = std::min(i0 + 1, int(t.width) - 1), j1 = std::min(j0 + 1, int(t.height) - 1);
  const double fx = std::clamp(x - i0, 0.0, 1.0), fy = std::clamp(y - j0, 0.0, 1.0);
  const auto at = [&](int i, int j) { return double(t.rgba[(size_t(j) * t.width + size_t(i)) * 4]); };
  return (1 - fy) * ((1 - fx) * at(i0, j0) + fx * at(i1, j0)) + fy * ((1 - fx) * at(i0, j1) + fx * at(i1, j1));
}

// The map's uv of the sun's ray from world point p.
inline std::pair<double, double> cloud_shadow_map_uv(const gpu::CloudShadowView& view, const Vec3& p) {
  const double s = (view.plane[1] - p[1]) / view.to_sun[1];
  return {(p[0] + s * view.to_sun[0] - view.plane[0]) / view.plane[3] + 0.5, (p[2] + s * view.to_sun[2] - view.plane[2]) / view.plane[3] + 0.5};
}

}  // namespace volgraph::testing
