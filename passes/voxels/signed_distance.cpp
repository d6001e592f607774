#include "passes/voxels/signed_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace volgraph::voxels {
namespace {

struct SdfTriangle {
  glm::dvec3 a, b, c;
  glm::dvec3 centre;  // the bounding sphere of the three corners: a lower bound on the distance
  double radius;
};

std::vector<SdfTriangle> sdf_triangles(const std::vector<float>& corners) {
  std::vector<SdfTriangle> triangles;
  for (size_t t = 0; t + 12 <= corners.size(); t += 12) {
    SdfTriangle s;
    s.a = {corners[t], corners[t + 1], corners[t + 2]};
    s.b = {corners[t + 4], corners[t + 5], corners[t + 6]};
    s.c = {corners[t + 8], corners[t + 9], corners[t + 10]};
    s.centre = (s.a + s.b + s.c) / 3.0;
    s.radius = std::sqrt(std::max({glm::dot(s.a - s.centre, s.a - s.centre), glm::dot(s.b - s.centre, s.b - s.centre),
                                   glm::dot(s.c - s.centre, s.c - s.centre)}));
    triangles.push_back(s);
  }
  return triangles;
}

double squared_distance(glm::dvec3 p, const SdfTriangle& t) {
  const glm::dvec3 q = closest_point_on_triangle(p, t.a, t.b, t.c) - p;
  return glm::dot(q, q);
}

// The squared distance to the nearest triangle, `nearest` its index (a good first guess in, the
// nearest out): triangles whose bounding sphere is farther than the best so far are skipped.
double nearest_squared_distance(glm::dvec3 p, const std::vector<SdfTriangle>& triangles, size_t& nearest) {
  double best = squared_distance(p, triangles[nearest]);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const double bound = glm::length(p - triangles[t].centre) - triangles[t].radius;
    if (bound > 0 && bound * bound >= best) continue;
    if (const double d = squared_distance(p, triangles[t]); d < best) best = d, nearest = t;
  }
  return best;
}

// 2D orientation of (p, q, r): twice the signed area.
double orient2d(glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); }

// Where the line {(x, y, z) : x ∈ ℝ} crosses the triangles: x and ±1 (+1 leaving through a face
// whose normal has +x). False when the line passes within `tolerance` of an edge or vertex.
bool line_crossings(double y, double z, const std::vector<SdfTriangle>& triangles, std::vector<std::pair<double, int>>& crossings) {
  constexpr double kTolerance = 1e-9;
  crossings.clear();
  const glm::dvec2 q(y, z);
  for (const SdfTriangle& t : triangles) {
    const glm::dvec2 a(t.a.y, t.a.z), b(t.b.y, t.b.z), c(t.c.y, t.c.z);
    if (q.x < std::min({a.x, b.x, c.x}) - kTolerance || q.x > std::max({a.x, b.x, c.x}) + kTolerance ||
        q.y < std::min({a.y, b.y, c.y}) - kTolerance || q.y > std::max({a.y, b.y, c.y}) + kTolerance)
      continue;
    const double area = orient2d(a, b, c);
    if (std::abs(area) <= kTolerance) continue;  // edge-on: its neighbours decide
    const double wa = orient2d(b, c, q) / area, wb = orient2d(c, a, q) / area, wc = orient2d(a, b, q) / area;
    if (std::min({wa, wb, wc}) < -kTolerance) continue;
    if (std::min({wa, wb, wc}) <= kTolerance) return false;  // on an edge or a vertex
    crossings.emplace_back(wa * t.a.x + wb * t.b.x + wc * t.c.x, area > 0 ? 1 : -1);
  }
  return true;
}

}  // namespace

glm::dvec3 closest_point_on_triangle(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;  // vertex region a
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;  // edge region ab
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;  // edge region ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);  // edge region bc
  const double denominator = 1.0 / (va + vb + vc);  // face region: barycentric (va, vb, vc)
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

double generalized_winding_number(glm::dvec3 p, const std::vector<float>& corners) {
  double solid_angles = 0;
  for (size_t t = 0; t + 12 <= corners.size(); t += 12) {
    const glm::dvec3 a = glm::dvec3(corners[t], corners[t + 1], corners[t + 2]) - p;
    const glm::dvec3 b = glm::dvec3(corners[t + 4], corners[t + 5], corners[t + 6]) - p;
    const glm::dvec3 c = glm::dvec3(corners[t + 8], corners[t + 9], corners[t + 10]) - p;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    // tan(Ω/2) = det(a, b, c) / (|a||b||c| + (a·b)|c| + (b·c)|a| + (c·a)|b|)
    solid_angles += 2.0 * std::atan2(glm::dot(a, glm::cross(b, c)), la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb);
  }
  return solid_angles / (4.0 * M_PI);
}

SignedDistanceField signed_distance_on_grid(const std::vector<float>& corners, int cells) {
  const int points = cells + 1;
  SignedDistanceField field;
  field.cells = cells;
  field.lines = int64_t(points) * points;
  field.distance.assign(size_t(points) * points * points, std::numeric_limits<float>::max());
  const std::vector<SdfTriangle> triangles = sdf_triangles(corners);
  if (triangles.empty()) return field;
  std::vector<std::pair<double, int>> crossings;
  size_t nearest = 0;
  for (int k = 0; k < points; ++k)
    for (int j = 0; j < points; ++j) {
      bool by_crossings = line_crossings(j, k, triangles, crossings);
      int winding_ahead = 0;  // Σ ±1 over the crossings at x > i
      for (const auto& [x, sign] : crossings) winding_ahead += sign;
      by_crossings = by_crossings && winding_ahead == 0;  // a closed mesh's crossings cancel along a whole line
      field.fallback_lines += !by_crossings;
      std::sort(crossings.begin(), crossings.end());
      size_t passed = 0;
      for (int i = 0; i < points; ++i) {
        const glm::dvec3 p(i, j, k);
        const double distance = std::sqrt(nearest_squared_distance(p, triangles, nearest));
        bool inside = false;
        if (by_crossings) {
          for (; passed < crossings.size() && crossings[passed].first <= i; ++passed) winding_ahead -= crossings[passed].second;
          inside = winding_ahead != 0;
        } else {
          inside = std::abs(generalized_winding_number(p, corners)) >= 0.5;
        }
        field.distance[(size_t(k) * points + size_t(j)) * points + size_t(i)] = float(inside ? -distance : distance);
      }
    }
  return field;
}

}  // namespace volgraph::voxels
