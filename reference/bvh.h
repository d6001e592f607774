// A bounding volume hierarchy over world-space triangles for the CPU reference renderer,
// in double precision: a binned surface-area-heuristic build (Wald 2007, "On fast
// Construction of SAH-based Bounding Volume Hierarchies"), closest-hit and any-hit ray
// queries, and Möller–Trumbore ray–triangle intersection.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "graph/scene/scene.h"

namespace volgraph::reference {

struct Triangle {
  Vec3 a, b, c;  // counter-clockwise seen from the front
};

// Points origin + t·direction with t in (t_min, t_max]; direction need not be unit.
struct Ray {
  Vec3 origin{0, 0, 0};
  Vec3 direction{0, 0, 1};
  double t_min = 0;
  double t_max = std::numeric_limits<double>::infinity();
};

// Where a ray meets a triangle: the point is (1 − u − v)·a + u·b + v·c.
struct TriangleHit {
  double t = 0;
  double u = 0, v = 0;
  uint32_t triangle = 0;  // index into the triangles the hierarchy was built from
};

// Möller & Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection": the hit in
// (t_min, t_max], edges and corners included; none for a degenerate triangle or a ray in
// its plane. `triangle` of the result is left 0.
std::optional<TriangleHit> intersect_triangle(const Triangle& tri, const Ray& ray);

class Bvh {
 public:
  explicit Bvh(std::vector<Triangle> triangles);

  // The nearest hit in (t_min, t_max]; ties go to the lower triangle index.
  std::optional<TriangleHit> closest_hit(const Ray& ray) const;
  // Whether any triangle is hit in (t_min, t_max].
  bool any_hit(const Ray& ray) const;

  size_t triangle_count() const { return triangles_.size(); }
  size_t node_count() const { return nodes_.size(); }
  const Triangle& triangle(uint32_t index) const { return triangles_[index]; }

 private:
  struct Box {
    Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()};
  };
  struct Node {
    Box bounds;
    uint32_t first = 0;  // leaf: first entry of order_; inner: index of the second child (the first follows the node)
    uint32_t count = 0;  // leaf: how many triangles; 0 for an inner node
  };
  struct Build;

  uint32_t build(Build& b, uint32_t begin, uint32_t end, uint32_t depth);

  std::vector<Triangle> triangles_;
  std::vector<uint32_t> order_;  // triangle indices, leaves' ranges
  std::vector<Node> nodes_;
};

}  // namespace volgraph::reference
