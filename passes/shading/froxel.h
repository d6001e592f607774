// The froxel grid's depth distribution (CPU twin of shaders/include/froxel.glsl): slice
// coordinate w ∈ [0, 1] ↔ view depth between near and far, linear or exponential.
#pragma once

#include <algorithm>
#include <cmath>

namespace volgraph::shading {

enum class FroxelDistribution { linear, exponential };

struct FroxelRange {
  double near = 0.1, far = 100;
  FroxelDistribution distribution = FroxelDistribution::exponential;
};

inline double froxel_depth(const FroxelRange& r, double w) {
  if (r.distribution == FroxelDistribution::linear) return r.near + (r.far - r.near) * w;
  return r.near * std::pow(r.far / r.near, w);
}

inline double froxel_w(const FroxelRange& r, double z) {
  if (r.distribution == FroxelDistribution::linear) return std::clamp((z - r.near) / (r.far - r.near), 0.0, 1.0);
  return std::clamp(std::log(std::max(z, r.near) / r.near) / std::log(r.far / r.near), 0.0, 1.0);
}

}  // namespace volgraph::shading
