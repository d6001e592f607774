// The signed distance on voxelize's grid points (passes/voxels/signed_distance.h): Ericson's
// closest point on a triangle in each Voronoi region; a box's field equal to the analytic box
// distance (the mesh is the box exactly); a tessellated sphere's within the tessellation's sag;
// the sign right at every point the tessellation cannot flip; the cost on the demo model.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "passes/voxels/signed_distance.h"
#include "passes/voxels/voxel_mesh.h"
#include "tests/support/source_dir.h"

namespace volgraph::voxels {
namespace {

TEST(SignedDistance, ClosestPointOnTriangleInEachRegion) {
  const glm::dvec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_EQ(closest_point_on_triangle({0.5, 0.5, 3}, a, b, c), glm::dvec3(0.5, 0.5, 0));  // face
  EXPECT_EQ(closest_point_on_triangle({-1, -1, 1}, a, b, c), a);                        // vertex a
  EXPECT_EQ(closest_point_on_triangle({3, -1, 0}, a, b, c), b);                         // vertex b
  EXPECT_EQ(closest_point_on_triangle({-1, 3, 0}, a, b, c), c);                         // vertex c
  EXPECT_EQ(closest_point_on_triangle({1, -2, 1}, a, b, c), glm::dvec3(1, 0, 0));       // edge ab
  EXPECT_EQ(closest_point_on_triangle({-2, 1, 0}, a, b, c), glm::dvec3(0, 1, 0));       // edge ac
  EXPECT_EQ(closest_point_on_triangle({2, 2, 0}, a, b, c), glm::dvec3(1, 1, 0));        // edge bc
}

Scene scene_with(Shape shape, Vec3 size, Vec3 translate) {
  Scene scene;
  Object object;
  object.shape = shape;
  object.size = size;
  object.transform.translate = translate;
  scene.objects.push_back(object);
  return scene;
}

struct GridField {
  gpu::VoxelGrid grid;
  SignedDistanceField field;
};

GridField field_of(const Scene& scene, int n) {
  const std::vector<Triangle> triangles = world_triangles(scene, 0);
  const gpu::VoxelGrid grid = grid_around(triangles, n);
  return {grid, signed_distance_on_grid(grid_corners(triangles, grid), n)};
}

// Grid point (i, j, k) in the world.
glm::dvec3 world_point(const gpu::VoxelGrid& grid, int i, int j, int k) {
  return glm::dvec3(grid.origin[0], grid.origin[1], grid.origin[2]) + double(grid.origin[3]) * glm::dvec3(i, j, k);
}

// A box mesh is the box: the field is the analytic box distance (voxel units) to float rounding.
TEST(SignedDistance, BoxFieldIsTheAnalyticBoxDistance) {
  const glm::dvec3 centre(0.2, -0.1, 0.3), half(0.5, 0.3, 0.4);
  const GridField g = field_of(scene_with(Shape::box, {1.0, 0.6, 0.8}, {centre.x, centre.y, centre.z}), 16);
  double worst = 0;
  int wrong_sign = 0;
  for (int k = 0; k <= 16; ++k)
    for (int j = 0; j <= 16; ++j)
      for (int i = 0; i <= 16; ++i) {
        const glm::dvec3 q = glm::abs(world_point(g.grid, i, j, k) - centre) - half;
        const double exact = (glm::length(glm::max(q, 0.0)) + std::min(std::max({q.x, q.y, q.z}), 0.0)) / g.grid.origin[3];
        worst = std::max(worst, std::abs(double(g.field.at(i, j, k)) - exact));
        wrong_sign += std::abs(exact) > 1e-3 && (exact < 0) != (g.field.at(i, j, k) < 0);
      }
  std::printf("box 16³: worst |field − exact| %.2e voxel, %lld of %lld lines by the winding number\n", worst,
              static_cast<long long>(g.field.fallback_lines), static_cast<long long>(g.field.lines));
  EXPECT_LE(worst, 1e-4);
  EXPECT_EQ(wrong_sign, 0);
}

// A sphere of 24 rings × 48 segments (vertices on the sphere, 7.5° apart) lies within
// r·(1 − cos 7.5°) of it, a bound on the sag: the field is the analytic |p − c| − r within it,
// the sign right beyond it. Measured: 0.034 voxel at 16³, 0.068 at 32³ (half the bound).
TEST(SignedDistance, SphereFieldWithinTheTessellationsSag) {
  const glm::dvec3 centre(0.1, 0.2, -0.05);
  const double r = 0.7;
  for (const int n : {16, 32}) {
    const GridField g = field_of(scene_with(Shape::sphere, {r, r, r}, {centre.x, centre.y, centre.z}), n);
    const double sag = r * (1 - std::cos(M_PI / 24)) / g.grid.origin[3];
    double worst = 0;
    int wrong_sign = 0;
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          const double exact = (glm::length(world_point(g.grid, i, j, k) - centre) - r) / g.grid.origin[3];
          worst = std::max(worst, std::abs(double(g.field.at(i, j, k)) - exact));
          wrong_sign += std::abs(exact) > sag && (exact < 0) != (g.field.at(i, j, k) < 0);
        }
    std::printf("sphere %d³: worst |field − exact| %.4f voxel (sag %.4f), %lld of %lld lines by the winding number\n", n, worst, sag,
                static_cast<long long>(g.field.fallback_lines), static_cast<long long>(g.field.lines));
    EXPECT_LE(worst, sag);
    EXPECT_EQ(wrong_sign, 0);
  }
}

// The winding number is 1 inside a closed mesh and 0 outside.
TEST(SignedDistance, WindingNumberOfABox) {
  const std::vector<Triangle> triangles = world_triangles(scene_with(Shape::box, {1, 1, 1}, {0, 0, 0}), 0);
  const gpu::VoxelGrid grid = grid_around(triangles, 4);
  const std::vector<float> corners = grid_corners(triangles, grid);
  EXPECT_NEAR(generalized_winding_number({2, 2, 2}, corners), 1.0, 1e-12);
  EXPECT_NEAR(generalized_winding_number({0.3, 3.1, 1.7}, corners), 1.0, 1e-12);
  EXPECT_NEAR(generalized_winding_number({5, 2, 2}, corners), 0.0, 1e-12);
  EXPECT_NEAR(generalized_winding_number({-3, 7, 1}, corners), 0.0, 1e-12);
}

// What the field costs on the demo model (no assertion on time: printed).
TEST(SignedDistance, CostOnTheDemoModel) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const LoadedConfig loaded = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/demo_voxels.json", registry);
  const std::vector<Triangle> triangles = world_triangles(loaded.config.scene, 0);
  for (const int n : {32, 64}) {
    const auto start = std::chrono::steady_clock::now();
    const SignedDistanceField field = signed_distance_on_grid(grid_corners(triangles, grid_around(triangles, n)), n);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int64_t inside = 0;
    for (const float d : field.distance) inside += d < 0;
    std::printf("Suzanne (%zu triangles) %d³: %zu points in %.2f s, %lld inside, %lld of %lld lines by the winding number\n",
                triangles.size(), n, field.distance.size(), seconds, static_cast<long long>(inside),
                static_cast<long long>(field.fallback_lines), static_cast<long long>(field.lines));
    EXPECT_GT(inside, 0);
  }
}

}  // namespace
}  // namespace volgraph::voxels
