// Primitive meshes: every triangle winds counter-clockwise about the outward normal its
// vertices carry, and areas are the shapes' (box exactly, sphere to tessellation).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "physics/camera.h"
#include "passes/plumbing/meshes.h"

namespace volgraph::plumbing {

using namespace physics;
namespace {

double at(const Mesh& m, uint32_t i, uint32_t k) { return m.vertices[kMeshVertexFloats * i + k]; }
Vec3 vertex(const Mesh& m, uint32_t i) { return {at(m, i, 0), at(m, i, 1), at(m, i, 2)}; }
Vec3 normal(const Mesh& m, uint32_t i) { return {at(m, i, 3), at(m, i, 4), at(m, i, 5)}; }
double u_of(const Mesh& m, uint32_t i) { return at(m, i, 6); }
double v_of(const Mesh& m, uint32_t i) { return at(m, i, 7); }
uint32_t vertex_count(const Mesh& m) { return uint32_t(m.vertices.size() / kMeshVertexFloats); }

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

TEST(Meshes, PlaneSpansTheImageOnceWithItsTopRowTowardMinusZ) {
  const Mesh m = primitive_mesh(Shape::plane, {4, 1, 2});
  ASSERT_EQ(vertex_count(m), 4u);
  for (uint32_t i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(u_of(m, i), vertex(m, i)[0] / 4 + 0.5);
    EXPECT_DOUBLE_EQ(v_of(m, i), vertex(m, i)[2] / 2 + 0.5);
  }
}

TEST(Meshes, EveryBoxFaceSpansTheImageUpright) {
  const Mesh m = primitive_mesh(Shape::box, {1, 2, 3});
  for (uint32_t face = 0; face < 6; ++face) {
    // Corners o, o+u, o+u+v, o+v carry (0,1), (1,1), (1,0), (0,0): v = 0 at the far end of v.
    const uint32_t o = 4 * face;
    const double expected[4][2] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (uint32_t k = 0; k < 4; ++k) {
      EXPECT_EQ(u_of(m, o + k), expected[k][0]) << "face " << face << " corner " << k;
      EXPECT_EQ(v_of(m, o + k), expected[k][1]) << "face " << face << " corner " << k;
    }
  }
  // The side faces' image is upright: v decreases with height.
  EXPECT_LT(v_of(m, 3), v_of(m, 0));
  EXPECT_GT(vertex(m, 3)[1], vertex(m, 0)[1]);
}

TEST(Meshes, SphereMapsLatitudeToVAndLongitudeToU) {
  const Mesh m = primitive_mesh(Shape::sphere, {0.5, 0.5, 0.5});
  for (uint32_t i = 0; i < vertex_count(m); ++i) {
    const Vec3 n = normal(m, i);
    ASSERT_NEAR(v_of(m, i), std::acos(std::clamp(n[1], -1.0, 1.0)) / M_PI, 1e-6) << i;  // v = θ / π from the north pole
    if (std::abs(n[1]) > 0.999) continue;  // longitude undefined at the poles
    const double phi = std::atan2(-n[2], n[0]);  // the mesh's longitude, counter-clockwise from +x seen from above
    const double u = u_of(m, i);
    const double expected = phi < 0 ? phi / (2 * M_PI) + 1 : phi / (2 * M_PI);
    ASSERT_TRUE(std::abs(u - expected) < 1e-6 || std::abs(u - expected - 1) < 1e-6 || std::abs(u - expected + 1) < 1e-6) << i;
  }
}

TEST(Meshes, SphereWindsOutwardAndApproachesItsArea) {
  const Mesh m = primitive_mesh(Shape::sphere, {0.5, 0.5, 0.5});
  EXPECT_NEAR(checked_area(m), 4 * M_PI * 0.25, 0.01 * 4 * M_PI * 0.25);  // tessellation: within 1 %
}

}  // namespace
}  // namespace volgraph::plumbing
