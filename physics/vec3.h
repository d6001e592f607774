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

// A unit vector at cosine `cos_theta` from unit `axis`, at azimuth φ about it (the
// Monte Carlo references' scattered directions).
inline Vec3 around(const Vec3& axis, double cos_theta, double phi) {
  const Vec3 helper = std::abs(axis[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 b1 = normalize(cross(axis, helper));
  const Vec3 b2 = cross(axis, b1);
  const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  return normalize(add(scaled(axis, cos_theta), add(scaled(b1, sin_theta * std::cos(phi)), scaled(b2, sin_theta * std::sin(phi)))));
}

}  // namespace volgraph::physics
