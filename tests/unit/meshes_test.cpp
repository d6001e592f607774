// Primitive meshes: every triangle winds counter-clockwise about the outward normal its
// vertices carry, and areas are the shapes' (box exactly, sphere to tessellation).
#include <cmath>

#include <gtest/gtest.h>

#include "passes/shading/camera.h"
#include "passes/shading/meshes.h"

namespace volgraph::shading {
namespace {

Vec3 vertex(const Mesh& m, uint32_t i) { return {m.vertices[6 * i], m.vertices[6 * i + 1], m.vertices[6 * i + 2]}; }
Vec3 normal(const Mesh& m, uint32_t i) { return {m.vertices[6 * i + 3], m.vertices[6 * i + 4], m.vertices[6 * i + 5]}; }

// Total area; fails the test where a triangle's winding disagrees with its normals.
double checked_area(const Mesh& m) {
  double area = 0;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    const Vec3 a = vertex(m, m.indices[t]), b = vertex(m, m.indices[t + 1]), c = vertex(m, m.indices[t + 2]);
    const Vec3 n = cross(sub(b, a), sub(c, a));
    const double twice = std::sqrt(dot(n, n));
    if (twice < 1e-12) continue;  // the sphere's pole triangles are degenerate
    area += twice / 2;
    EXPECT_GT(dot(n, normal(m, m.indices[t])), 0) << "triangle " << t / 3;
  }
  return area;
}

TEST(Meshes, BoxWindsOutwardWithTheRightArea) {
  const Mesh m = primitive_mesh(Shape::box, {1, 2, 3});
  EXPECT_EQ(m.indices.size(), 36u);
  EXPECT_NEAR(checked_area(m), 2 * (1 * 2 + 2 * 3 + 3 * 1), 1e-9);
}

TEST(Meshes, PlaneFacesUpWithTheRightArea) {
  const Mesh m = primitive_mesh(Shape::plane, {4, 1, 2});
  EXPECT_NEAR(checked_area(m), 8, 1e-9);
  for (uint32_t i = 0; i < 4; ++i) EXPECT_EQ(normal(m, i)[1], 1.0);
}

TEST(Meshes, SphereWindsOutwardAndApproachesItsArea) {
  const Mesh m = primitive_mesh(Shape::sphere, {0.5, 0.5, 0.5});
  EXPECT_NEAR(checked_area(m), 4 * M_PI * 0.25, 0.01 * 4 * M_PI * 0.25);  // tessellation: within 1 %
}

}  // namespace
}  // namespace volgraph::shading
