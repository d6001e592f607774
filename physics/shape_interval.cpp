#include "physics/shape_interval.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace volgraph::physics {
namespace {

double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

std::optional<RayInterval> unit_box_interval(const Vec3& o, const Vec3& d) {
  double enter = -std::numeric_limits<double>::infinity(), exit = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (std::abs(o[k]) > 0.5) return std::nullopt;
      continue;
    }
    double a = (-0.5 - o[k]) / d[k], b = (0.5 - o[k]) / d[k];
    if (a > b) std::swap(a, b);
    enter = std::max(enter, a);
    exit = std::min(exit, b);
  }
  if (enter > exit) return std::nullopt;
  return RayInterval{enter, exit};
}

std::optional<RayInterval> unit_ball_interval(const Vec3& o, const Vec3& d) {
  const double a = dot3(d, d), b = 2 * dot3(o, d), c = dot3(o, o) - 1;
  const double discriminant = b * b - 4 * a * c;
  if (a == 0 || discriminant < 0) return std::nullopt;
  const double q = -(b + std::copysign(std::sqrt(discriminant), b)) / 2;
  if (q == 0) return RayInterval{0, 0};
  const double r1 = q / a, r2 = c / q;
  return RayInterval{std::min(r1, r2), std::max(r1, r2)};
}

std::optional<RayInterval> unit_shape_interval(Shape shape, const Vec3& origin, const Vec3& direction) {
  return shape == Shape::box ? unit_box_interval(origin, direction) : unit_ball_interval(origin, direction);
}

Vec3 unit_shape_scale(const MediumVolume& v) {
  return v.shape == Shape::sphere ? Vec3{v.size[0], v.size[0], v.size[0]} : v.size;
}

}  // namespace volgraph::physics
