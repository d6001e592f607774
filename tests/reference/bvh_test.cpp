// The reference renderer's BVH against brute force: on random triangle soups (with
// degenerate and axis-aligned triangles, rays parallel to axes, rays starting inside the
// soup) the closest hit is the same distance as the nearest of all triangles, and any-hit
// agrees with "some triangle is hit" for random ranges.
#include <gtest/gtest.h>

#include "reference/bvh.h"
#include "tests/support/random_graph.h"

namespace volgraph::reference {
namespace {

using test::Rng;

Vec3 random_point(Rng& rng, double extent) {
  return {(rng.unit() * 2 - 1) * extent, (rng.unit() * 2 - 1) * extent, (rng.unit() * 2 - 1) * extent};
}

// A corner near `centre`, within half a metre.
Vec3 corner_near(Rng& rng, const Vec3& centre) {
  const Vec3 d = random_point(rng, 0.5);
  return {centre[0] + d[0], centre[1] + d[1], centre[2] + d[2]};
}

// Small triangles scattered in a cube, some degenerate, some in axis planes.
std::vector<Triangle> triangle_soup(Rng& rng, size_t count) {
  std::vector<Triangle> soup;
  for (size_t i = 0; i < count; ++i) {
    const Vec3 centre = random_point(rng, 5);
    Triangle t{centre, corner_near(rng, centre), corner_near(rng, centre)};
    if (i % 17 == 0) t.c = t.b;                                  // degenerate: a segment
    if (i % 13 == 0) t.a[1] = t.b[1] = t.c[1] = centre[1];       // in a plane y = const
    soup.push_back(t);
  }
  return soup;
}

Ray random_ray(Rng& rng, size_t index) {
  Ray r;
  r.origin = index % 3 == 0 ? random_point(rng, 4) : random_point(rng, 12);  // a third start inside the soup
  const Vec3 aim = random_point(rng, 5);  // most rays head into the soup
  r.direction = index % 5 == 0 ? random_point(rng, 1) : Vec3{aim[0] - r.origin[0], aim[1] - r.origin[1], aim[2] - r.origin[2]};
  if (index % 7 == 0) {  // along an axis: the slab test's division by zero
    r.direction = {0, 0, 0};
    r.direction[index % 3] = rng.chance(0.5) ? 1 : -1;
  }
  r.t_min = rng.chance(0.5) ? 0 : rng.unit();
  r.t_max = rng.chance(0.5) ? std::numeric_limits<double>::infinity() : 1 + rng.unit() * 20;
  return r;
}

std::optional<TriangleHit> brute_force_closest(const std::vector<Triangle>& soup, const Ray& ray) {
  std::optional<TriangleHit> best;
  for (uint32_t i = 0; i < soup.size(); ++i) {
    std::optional<TriangleHit> h = intersect_triangle(soup[i], ray);
    if (h && (!best || h->t < best->t)) {
      best = h;
      best->triangle = i;
    }
  }
  return best;
}

TEST(Bvh, ClosestAndAnyHitMatchBruteForceOnRandomSoups) {
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    Rng rng(seed);
    const std::vector<Triangle> soup = triangle_soup(rng, 1000 + 500 * seed);
    const Bvh bvh(soup);
    ASSERT_EQ(bvh.triangle_count(), soup.size());
    size_t hits = 0;
    for (size_t r = 0; r < 3000; ++r) {
      const Ray ray = random_ray(rng, r);
      const std::optional<TriangleHit> expected = brute_force_closest(soup, ray);
      const std::optional<TriangleHit> got = bvh.closest_hit(ray);
      ASSERT_EQ(expected.has_value(), got.has_value()) << "seed " << seed << " ray " << r;
      ASSERT_EQ(bvh.any_hit(ray), expected.has_value()) << "seed " << seed << " ray " << r;
      if (!expected) continue;
      ++hits;
      EXPECT_EQ(got->t, expected->t) << "seed " << seed << " ray " << r;
      EXPECT_EQ(intersect_triangle(soup[got->triangle], ray)->t, got->t);  // the reported triangle is the one hit
    }
    EXPECT_GT(hits, 600u) << "the soup should stop a good share of the rays";
    // A hierarchy, not a list: leaves hold at most 4 triangles here (no centroids coincide).
    EXPECT_GE(bvh.node_count(), soup.size() / 2) << "seed " << seed;
  }
}

TEST(Bvh, EmptyAndSingleTriangle) {
  const Bvh empty({});
  EXPECT_FALSE(empty.closest_hit({}).has_value());
  EXPECT_FALSE(empty.any_hit({}));
  const Bvh one({{{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}}});
  const std::optional<TriangleHit> h = one.closest_hit({{0, 0, 0}, {0, 0, 1}});
  ASSERT_TRUE(h);
  EXPECT_EQ(h->t, 2.0);
  EXPECT_FALSE(one.any_hit({{0, 0, 0}, {0, 0, 1}, 0, 1.5}));  // beyond t_max
  EXPECT_FALSE(one.any_hit({{0, 0, 0}, {0, 0, -1}}));        // behind the origin
}

TEST(Bvh, SharedEdgeIsNotACrack) {
  // Two triangles of a quad: a ray through the shared diagonal hits (edges are inclusive).
  const Bvh quad({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}});
  for (double x : {0.25, 0.5, 0.75}) {
    EXPECT_TRUE(quad.closest_hit({{x, x, 1}, {0, 0, -1}}).has_value()) << x;
  }
}

}  // namespace
}  // namespace volgraph::reference
