// Cube-face meshes of voxel grids (passes/voxels/voxel_faces.h, RTR4 13.10): the culled face
// counts and the greedy quad counts on shapes whose counts follow by hand, greedy quads covering
// exactly the culled faces on a random grid, and the counts for the demo model.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <random>
#include <tuple>

#include <nlohmann/json.hpp>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "passes/voxels/voxel_faces.h"
#include "passes/voxels/voxel_mesh.h"
#include "tests/support/source_dir.h"

namespace volgraph::voxels {
namespace {

// An n³ grid with the listed voxels solid.
std::vector<uint8_t> grid_with(int n, const std::vector<glm::ivec3>& voxels) {
  std::vector<uint8_t> solid(size_t(n) * n * n, 0);
  for (const glm::ivec3 v : voxels) solid[(size_t(v.z) * n + v.y) * n + v.x] = 1;
  return solid;
}

struct FaceCounts {
  size_t culled, greedy;
};

FaceCounts culled_and_greedy_counts(const std::vector<uint8_t>& solid, int n) { return {culled_faces(solid, n).size(), greedy_faces(solid, n).size()}; }

using UnitFace = std::tuple<int, int, int, int, int, int>;  // least corner, normal

// How often each unit face is covered by the quads.
std::map<UnitFace, int> unit_face_cover(const std::vector<FaceQuad>& quads) {
  std::map<UnitFace, int> cover;
  for (const FaceQuad& q : quads) {
    const glm::ivec3 extent = glm::max(q.size, glm::ivec3(1));  // 1 across the plane
    for (int z = 0; z < extent.z; ++z)
      for (int y = 0; y < extent.y; ++y)
        for (int x = 0; x < extent.x; ++x)
          ++cover[{q.corner.x + x, q.corner.y + y, q.corner.z + z, q.normal.x, q.normal.y, q.normal.z}];
  }
  return cover;
}

TEST(VoxelFaces, ASingleVoxelHasSixFacesBothWays) {
  const FaceCounts c = culled_and_greedy_counts(grid_with(3, {{1, 1, 1}}), 3);
  EXPECT_EQ(c.culled, 6u);
  EXPECT_EQ(c.greedy, 6u);
}

// A solid n³ box: 6n² faces on its outside, none inside; each side one rectangle.
TEST(VoxelFaces, ASolidBoxIsSixQuads) {
  for (const int n : {1, 2, 5, 8}) {
    const FaceCounts c = culled_and_greedy_counts(std::vector<uint8_t>(size_t(n) * n * n, 1), n);
    EXPECT_EQ(c.culled, size_t(6 * n * n)) << "n " << n;
    EXPECT_EQ(c.greedy, 6u) << "n " << n;
  }
}

// Two voxels sharing a face: 12 − 2 culled; the four long sides merge into 1×2 quads.
TEST(VoxelFaces, TwoVoxelsSideBySide) {
  const FaceCounts c = culled_and_greedy_counts(grid_with(4, {{1, 1, 1}, {2, 1, 1}}), 4);
  EXPECT_EQ(c.culled, 10u);
  EXPECT_EQ(c.greedy, 6u);
}

// An L of three voxels in the plane z = 0: (0,0,0), (1,0,0), (0,1,0). Two shared faces, so
// culled 18 − 4 = 14. Greedy: −z and +z each the L, 2 rectangles (2×1 and 1×1); −x one 1×2
// column at x = 0; −y one 2×1 row at y = 0; +x two (x = 1 for (0,1,0), x = 2 for (1,0,0));
// +y two (y = 1 for (1,0,0), y = 2 for (0,1,0)): 2 + 2 + 1 + 1 + 2 + 2 = 10.
TEST(VoxelFaces, AnLShape) {
  const FaceCounts c = culled_and_greedy_counts(grid_with(3, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), 3);
  EXPECT_EQ(c.culled, 14u);
  EXPECT_EQ(c.greedy, 10u);
}

// A checkerboard slab one voxel thick: solid voxels touch only along edges, so nothing is
// culled and nothing merges (coplanar faces meeting at a corner are not one rectangle):
// culled = greedy = 6 × (n² / 2) = 48 for n = 4.
TEST(VoxelFaces, ACheckerboardSlabNeitherCullsNorMerges) {
  const int n = 4;
  std::vector<glm::ivec3> black;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if ((x + y) % 2 == 0) black.push_back({x, y, 0});
  const FaceCounts c = culled_and_greedy_counts(grid_with(n, black), n);
  EXPECT_EQ(c.culled, 48u);
  EXPECT_EQ(c.greedy, 48u);
}

// On a random half-full grid, the greedy quads cover every culled face exactly once and no other face.
TEST(VoxelFaces, GreedyQuadsCoverExactlyTheCulledFaces) {
  const int n = 12;
  std::mt19937 random(20261205);
  std::vector<uint8_t> solid(size_t(n) * n * n);
  for (uint8_t& s : solid) s = uint8_t(random() % 2);
  const std::vector<FaceQuad> culled = culled_faces(solid, n);
  const std::vector<FaceQuad> greedy = greedy_faces(solid, n);
  int64_t greedy_area = 0;
  for (const FaceQuad& q : greedy) greedy_area += face_count(q);
  EXPECT_EQ(greedy_area, int64_t(culled.size()));
  const std::map<UnitFace, int> culled_cover = unit_face_cover(culled);
  const std::map<UnitFace, int> greedy_cover = unit_face_cover(greedy);
  for (const auto& [face, times] : greedy_cover) EXPECT_EQ(times, 1) << "a unit face covered twice";
  EXPECT_EQ(greedy_cover, culled_cover);
  EXPECT_LT(greedy.size(), culled.size());
  std::printf("random %d³ half full: culled %zu, greedy %zu\n", n, culled.size(), greedy.size());
}

// The demo model (configs/demo_voxels.json's voxelized object at its resolution) as naive cubes
// (6 faces per solid voxel), culled faces and greedy quads, as RTR4 13.10's figure reports them.
// The quads as triangles: two a quad, counter-clockwise seen from the normal's side (their
// cross product along the normal), their areas summing to the quads' (world = origin + side · p).
TEST(VoxelFaces, TrianglesAreTwoPerQuadFacingTheNormal) {
  std::mt19937 random(11);
  std::bernoulli_distribution half(0.5);
  const int n = 6;
  std::vector<uint8_t> solid(size_t(n) * n * n);
  for (uint8_t& s : solid) s = half(random);
  const std::vector<FaceQuad> quads = greedy_faces(solid, n);
  const float side = 0.25f;
  const FaceTriangles mesh = face_triangles(quads, glm::vec3(1, -2, 3), side);
  ASSERT_EQ(mesh.indices.size(), 6 * quads.size());
  ASSERT_EQ(mesh.vertices.size(), 4 * kFaceVertexFloats * quads.size());
  const auto position = [&](uint32_t v) { return glm::dvec3(mesh.vertices[v * kFaceVertexFloats], mesh.vertices[v * kFaceVertexFloats + 1], mesh.vertices[v * kFaceVertexFloats + 2]); };
  for (size_t q = 0; q < quads.size(); ++q) {
    double area = 0;
    for (size_t t = 2 * q; t < 2 * q + 2; ++t) {
      const glm::dvec3 a = position(mesh.indices[3 * t]), b = position(mesh.indices[3 * t + 1]), c = position(mesh.indices[3 * t + 2]);
      const glm::dvec3 normal_times_twice_area = glm::cross(b - a, c - a);
      EXPECT_GT(glm::dot(normal_times_twice_area, glm::dvec3(quads[q].normal)), 0) << "quad " << q;
      EXPECT_NEAR(glm::length(glm::cross(normal_times_twice_area, glm::dvec3(quads[q].normal))), 0, 1e-9) << "quad " << q;
      area += 0.5 * glm::length(normal_times_twice_area);
    }
    EXPECT_NEAR(area, double(face_count(quads[q])) * side * side, 1e-9) << "quad " << q;
  }
}

TEST(VoxelFaces, TheDemoModelsQuadCounts) {
  const std::string path = std::string(::volgraph::testing::source_dir()) + "/configs/demo_voxels.json";
  PassRegistry registry;
  register_builtin_passes(registry);
  const LoadedConfig loaded = load_config(path, registry);
  const nlohmann::json config = nlohmann::json::parse(std::ifstream(path));
  nlohmann::json voxelize_params;
  for (const nlohmann::json& pass : config["graph"]["passes"])
    if (pass["type"] == "voxelize") voxelize_params = pass["params"];
  const int n = voxelize_params["resolution"];
  const std::vector<Triangle> triangles = world_triangles(loaded.config.scene, voxelize_params["object"]);
  const std::vector<uint8_t> solid = voxelize_on_cpu(grid_corners(triangles, grid_around(triangles, n)), n);
  size_t voxels = 0;
  for (const uint8_t s : solid) voxels += s != 0;
  const FaceCounts c = culled_and_greedy_counts(solid, n);
  std::printf("demo_voxels %d³: %zu solid voxels; naive %zu faces, culled %zu, greedy %zu quads\n", n, voxels,
              6 * voxels, c.culled, c.greedy);
  EXPECT_GT(voxels, 0u);
  EXPECT_LT(c.culled, 6 * voxels);
  EXPECT_LT(c.greedy, c.culled);
}

}  // namespace
}  // namespace volgraph::voxels
