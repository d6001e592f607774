// The scene's Vec3 (std::array<double, 3>) as a vector and as an rgb triple: the helpers
// passes/, reference/, physics/ and tests/ share (physics/ otherwise computes with
// glm::dvec3). One definition each, so that no file keeps its own copy.
#pragma once

#include <algorithm>
#include <cmath>

#include "graph/scene/scene.h"

namespace volgraph::physics {

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 scaled(const Vec3& v, double s) { return {v[0] * s, v[1] * s, v[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length_of(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline Vec3 normalize(const Vec3& v) {
  const double l = std::sqrt(dot(v, v));
  return {v[0] / l, v[1] / l, v[2] / l};
}

// Per channel (rgb): a·b, a·s, a/b, e^(−v); the largest channel; all three zero.
inline Vec3 times(const Vec3& a, const Vec3& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }
inline Vec3 times(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline Vec3 over(const Vec3& a, const Vec3& b) { return {a[0] / b[0], a[1] / b[1], a[2] / b[2]}; }
inline Vec3 exp_negative(const Vec3& v) { return {std::exp(-v[0]), std::exp(-v[1]), std::exp(-v[2])}; }
inline double largest(const Vec3& v) { return std::max({v[0], v[1], v[2]}); }
inline bool is_zero(const Vec3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

}  // namespace volgraph::physics
