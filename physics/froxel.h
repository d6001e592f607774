// The froxel grid's depth distribution (CPU twin of shaders/include/froxel.glsl): slice
// coordinate w ∈ [0, 1] ↔ view depth between near and far, linear or exponential; and
// where a world point falls in a view's grid (temporal reprojection).
#pragma once

#include <algorithm>
#include <cmath>

#include "physics/camera.h"

namespace volgraph::physics {

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
  if (r.distribution == FroxelDistribution::linear) return glm::clamp((z - r.near) / (r.far - r.near), 0.0, 1.0);
  return glm::clamp(std::log(std::max(z, r.near) / r.near) / std::log(r.far / r.near), 0.0, 1.0);
}

// Where world point p falls in the grid (range r) of view v (froxel.glsl `froxel_uvw`,
// Hillaire 2015's reprojection): the grid volumes' texture coordinate, and whether it is
// inside the grid.
struct FroxelUvw {
  double u = 0, v = 0, w = 0;
  bool inside = false;
};

inline FroxelUvw froxel_uvw(const ViewRays& v, const FroxelRange& r, const Vec3& p) {
  const ViewUvz uvz = view_uvz(v, p);
  const bool inside = uvz.u >= 0 && uvz.u <= 1 && uvz.v >= 0 && uvz.v <= 1 && uvz.z >= r.near && uvz.z <= r.far;
  return {uvz.u, uvz.v, froxel_w(r, uvz.z), inside};
}

}  // namespace volgraph::physics
