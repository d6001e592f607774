#include "reference/bvh.h"

#include <algorithm>
#include <array>

#include "physics/camera.h"

namespace volgraph::reference {
namespace {

using physics::cross;
using physics::dot;
using physics::sub;

constexpr uint32_t kBins = 16;
constexpr uint32_t kMaxLeafSize = 4;  // a leaf may hold more only when its centroids coincide
constexpr uint32_t kMaxDepth = 100;       // deeper ranges become leaves, so traversal stacks stay bounded
constexpr size_t kStackDepth = kMaxDepth + 2;

double surface_area(const Vec3& lo, const Vec3& hi) {
  if (lo[0] > hi[0]) return 0;
  const Vec3 e = sub(hi, lo);
  return 2 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
}

void grow(Vec3& lo, Vec3& hi, const Vec3& p) {
  for (size_t k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], p[k]);
    hi[k] = std::max(hi[k], p[k]);
  }
}

// The union of two boxes (an empty box, lo = +∞ and hi = −∞, changes nothing).
template <typename Box>
void merge(Box& into, const Box& other) {
  for (size_t k = 0; k < 3; ++k) {
    into.lo[k] = std::min(into.lo[k], other.lo[k]);
    into.hi[k] = std::max(into.hi[k], other.hi[k]);
  }
}

// 1/d per axis (±∞ for a zero component), for the slab test.
Vec3 inverse_direction(const Vec3& d) { return {1.0 / d[0], 1.0 / d[1], 1.0 / d[2]}; }

// The parameter interval where the ray is inside [lo, hi], clipped to [t0, t1]; the far
// end is widened by 1 + 2γ₃ so that rounding never culls a box the ray touches (Ize 2013,
// "Robust BVH Ray Traversal", section 3).
bool slab_test(const Vec3& lo, const Vec3& hi, const Vec3& origin, const Vec3& inv, double t0, double t1, double& entry) {
  constexpr double kWiden = 1 + 2 * (3 * std::numeric_limits<double>::epsilon() / 2) / (1 - 3 * std::numeric_limits<double>::epsilon() / 2);
  for (size_t k = 0; k < 3; ++k) {
    if (std::isinf(inv[k])) {  // parallel to the slab: inside it or never
      if (origin[k] < lo[k] || origin[k] > hi[k]) return false;
      continue;
    }
    double near = (lo[k] - origin[k]) * inv[k], far = (hi[k] - origin[k]) * inv[k];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far * kWiden);
    if (t0 > t1) return false;
  }
  entry = t0;
  return true;
}

}  // namespace

std::optional<TriangleHit> intersect_triangle(const Triangle& tri, const Ray& ray) {
  const Vec3 e1 = sub(tri.b, tri.a), e2 = sub(tri.c, tri.a);
  const Vec3 p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (det == 0 || !std::isfinite(det)) return std::nullopt;
  const double inv = 1.0 / det;
  const Vec3 s = sub(ray.origin, tri.a);
  const double u = dot(s, p) * inv;
  if (u < 0 || u > 1) return std::nullopt;
  const Vec3 q = cross(s, e1);
  const double v = dot(ray.direction, q) * inv;
  if (v < 0 || u + v > 1) return std::nullopt;
  const double t = dot(e2, q) * inv;
  if (!(t > ray.t_min && t <= ray.t_max)) return std::nullopt;
  return TriangleHit{t, u, v, 0};
}

struct Bvh::Build {
  std::vector<Box> boxes;
  std::vector<Vec3> centroids;
};

Bvh::Bvh(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
  Build b;
  b.boxes.resize(triangles_.size());
  b.centroids.resize(triangles_.size());
  order_.resize(triangles_.size());
  for (uint32_t i = 0; i < triangles_.size(); ++i) {
    const Triangle& t = triangles_[i];
    for (const Vec3& p : {t.a, t.b, t.c}) grow(b.boxes[i].lo, b.boxes[i].hi, p);
    for (size_t k = 0; k < 3; ++k) b.centroids[i][k] = (b.boxes[i].lo[k] + b.boxes[i].hi[k]) / 2;
    order_[i] = i;
  }
  nodes_.reserve(2 * triangles_.size() + 1);
  build(b, 0, uint32_t(triangles_.size()), 0);
}

uint32_t Bvh::build(Build& b, uint32_t begin, uint32_t end, uint32_t depth) {
  const uint32_t index = uint32_t(nodes_.size());
  nodes_.push_back({});
  Box bounds, centroid_bounds;
  for (uint32_t i = begin; i < end; ++i) {
    merge(bounds, b.boxes[order_[i]]);
    grow(centroid_bounds.lo, centroid_bounds.hi, b.centroids[order_[i]]);
  }
  nodes_[index].bounds = bounds;
  const uint32_t count = end - begin;
  auto make_leaf = [&] {
    nodes_[index].first = begin;
    nodes_[index].count = count;
    return index;
  };
  if (count <= 1 || depth >= kMaxDepth) return make_leaf();

  // The best binned split over the three axes: cost A_L·N_L + A_R·N_R, against the
  // leaf's N·A plus one traversal step A (a box test costs about a triangle test).
  double best_cost = std::numeric_limits<double>::infinity();
  size_t best_axis = 0;
  uint32_t best_bin = 0;
  auto bin_of = [&](uint32_t tri, size_t axis) {
    const double extent = centroid_bounds.hi[axis] - centroid_bounds.lo[axis];
    const double x = (b.centroids[tri][axis] - centroid_bounds.lo[axis]) / extent * kBins;
    return std::min(uint32_t(x), kBins - 1);
  };
  for (size_t axis = 0; axis < 3; ++axis) {
    if (!(centroid_bounds.hi[axis] > centroid_bounds.lo[axis])) continue;
    std::array<Box, kBins> bin_boxes;
    std::array<uint32_t, kBins> bin_counts{};
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t bin = bin_of(order_[i], axis);
      ++bin_counts[bin];
      merge(bin_boxes[bin], b.boxes[order_[i]]);
    }
    std::array<double, kBins> right_cost{};
    Box right;
    uint32_t right_count = 0;
    for (uint32_t bin = kBins - 1; bin > 0; --bin) {
      merge(right, bin_boxes[bin]);
      right_count += bin_counts[bin];
      right_cost[bin] = surface_area(right.lo, right.hi) * right_count;
    }
    Box left;
    uint32_t left_count = 0;
    for (uint32_t split = 1; split < kBins; ++split) {  // bins [0, split) go left
      merge(left, bin_boxes[split - 1]);
      left_count += bin_counts[split - 1];
      if (left_count == 0 || left_count == count) continue;
      const double cost = surface_area(left.lo, left.hi) * left_count + right_cost[split];
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_bin = split;
      }
    }
  }
  const double leaf_cost = surface_area(bounds.lo, bounds.hi) * count;
  if (!std::isfinite(best_cost)) return make_leaf();  // every centroid in one place
  if (count <= kMaxLeafSize && leaf_cost <= best_cost + surface_area(bounds.lo, bounds.hi)) return make_leaf();

  const uint32_t* middle = std::partition(order_.data() + begin, order_.data() + end,
                                          [&](uint32_t tri) { return bin_of(tri, best_axis) < best_bin; });
  const uint32_t split = uint32_t(middle - order_.data());
  build(b, begin, split, depth + 1);
  const uint32_t second = build(b, split, end, depth + 1);
  nodes_[index].first = second;
  return index;
}

std::optional<TriangleHit> Bvh::closest_hit(const Ray& ray) const {
  if (triangles_.empty()) return std::nullopt;
  const Vec3 inv = inverse_direction(ray.direction);
  std::optional<TriangleHit> best;
  double t_max = ray.t_max;
  struct Entry {
    uint32_t node;
    double t;  // where the ray enters its box
  };
  std::array<Entry, kStackDepth> stack;
  size_t top = 0;
  double root_entry = 0;
  if (!slab_test(nodes_[0].bounds.lo, nodes_[0].bounds.hi, ray.origin, inv, ray.t_min, t_max, root_entry)) return best;
  stack[top++] = {0, root_entry};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.t > t_max) continue;
    const Node& node = nodes_[e.node];
    if (node.count > 0) {
      for (uint32_t i = node.first; i < node.first + node.count; ++i) {
        const uint32_t tri = order_[i];
        const std::optional<TriangleHit> h = intersect_triangle(triangles_[tri], {ray.origin, ray.direction, ray.t_min, t_max});
        if (!h || (best && h->t == best->t && tri > best->triangle)) continue;
        best = *h;
        best->triangle = tri;
        t_max = h->t;
      }
      continue;
    }
    // Both children whose boxes the ray enters, the nearer on top.
    const uint32_t first = e.node + 1, second = node.first;
    double t1 = 0, t2 = 0;
    const bool hit1 = slab_test(nodes_[first].bounds.lo, nodes_[first].bounds.hi, ray.origin, inv, ray.t_min, t_max, t1);
    const bool hit2 = slab_test(nodes_[second].bounds.lo, nodes_[second].bounds.hi, ray.origin, inv, ray.t_min, t_max, t2);
    if (hit1 && hit2 && t1 <= t2) {
      stack[top++] = {second, t2};
      stack[top++] = {first, t1};
    } else if (hit1 && hit2) {
      stack[top++] = {first, t1};
      stack[top++] = {second, t2};
    } else if (hit1) {
      stack[top++] = {first, t1};
    } else if (hit2) {
      stack[top++] = {second, t2};
    }
  }
  return best;
}

bool Bvh::any_hit(const Ray& ray) const {
  if (triangles_.empty()) return false;
  const Vec3 inv = inverse_direction(ray.direction);
  std::array<uint32_t, kStackDepth> stack;
  size_t top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const Node& node = nodes_[index];
    double entry = 0;
    if (!slab_test(node.bounds.lo, node.bounds.hi, ray.origin, inv, ray.t_min, ray.t_max, entry)) continue;
    if (node.count == 0) {
      stack[top++] = node.first;
      stack[top++] = index + 1;
      continue;
    }
    for (uint32_t i = node.first; i < node.first + node.count; ++i) {
      if (intersect_triangle(triangles_[order_[i]], ray)) return true;
    }
  }
  return false;
}

}  // namespace volgraph::reference
