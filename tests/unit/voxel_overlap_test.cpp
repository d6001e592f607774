// Akenine-Möller's triangle–box overlap test (shaders/include/voxel_overlap.h, RTR4 22.12) on
// known cases around voxel (0, 0, 0) = [0, 1]³, and the CPU twin's shell of a grid-aligned box.
#include <gtest/gtest.h>

#include <numeric>

#include "passes/voxels/voxel_mesh.h"
#include "passes/voxels/voxel_overlap.h"

namespace volgraph::voxels {
namespace {

using glm::vec3;

bool overlaps(vec3 a, vec3 b, vec3 c) { return overlap::voxel_overlaps(glm::ivec3(0), a, b, c); }

TEST(VoxelOverlap, ATriangleInsideTheBoxOverlaps) {
  EXPECT_TRUE(overlaps(vec3(0.2f, 0.2f, 0.5f), vec3(0.8f, 0.2f, 0.5f), vec3(0.5f, 0.8f, 0.5f)));
}

TEST(VoxelOverlap, ABoxInsideALargeTriangleOverlaps) {
  EXPECT_TRUE(overlaps(vec3(-10, -10, 0.5f), vec3(10, -10, 0.5f), vec3(0, 10, 0.5f)));
}

// Just outside each face (by 1e-3): separated by that box normal.
TEST(VoxelOverlap, ATriangleJustOutsideEachFaceDoesNot) {
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-1e-3f, 1.001f}) {
      vec3 a(0.2f, 0.3f, 0.4f), b(0.8f, 0.3f, 0.6f), c(0.5f, 0.7f, 0.5f);
      a[axis] = b[axis] = c[axis] = side;
      EXPECT_FALSE(overlaps(a, b, c)) << "axis " << axis << " at " << side;
      a[axis] = b[axis] = c[axis] = side < 0 ? 0.0f : 1.0f;  // on the face: touching counts
      EXPECT_TRUE(overlaps(a, b, c)) << "axis " << axis << " on the face";
    }
}

// Inside the bounding boxes but off the triangle's plane: only the triangle's normal separates.
TEST(VoxelOverlap, ThePlaneSeparatesATiltedTriangleNearACorner) {
  // The plane x + y + z = 3.01 misses the box (its farthest corner has 3) though the triangle's box spans it.
  EXPECT_FALSE(overlaps(vec3(3.01f, 0, 0), vec3(0, 3.01f, 0), vec3(0, 0, 3.01f)));
  EXPECT_TRUE(overlaps(vec3(2.99f, 0, 0), vec3(0, 2.99f, 0), vec3(0, 0, 2.99f)));
}

// Only an edge × edge axis separates: a flat triangle in the plane z = 0.5 (which cuts the box)
// whose bounding box overlaps the box's, its edge x + y = 2.1 passing beyond the corner line
// x = y = 1; the axis z × that edge separates them. Moved to x + y = 2 the edge touches it.
TEST(VoxelOverlap, AnEdgeAxisSeparatesATrianglePastACorner) {
  EXPECT_FALSE(overlaps(vec3(1.6f, 0.5f, 0.5f), vec3(0.5f, 1.6f, 0.5f), vec3(1.6f, 1.6f, 0.5f)));
  EXPECT_TRUE(overlaps(vec3(1.5f, 0.5f, 0.5f), vec3(0.5f, 1.5f, 0.5f), vec3(1.5f, 1.5f, 0.5f)));
}

// A triangle in the vertical plane x + y = 2.1, past the box's edge: its own normal separates it.
TEST(VoxelOverlap, AVerticalTrianglePastAnEdgeIsSeparated) {
  EXPECT_FALSE(overlaps(vec3(1.6f, 0.5f, -1), vec3(0.5f, 1.6f, -1), vec3(1.05f, 1.05f, 2)));
  // In x + y = 2, through the edge itself: touching.
  EXPECT_TRUE(overlaps(vec3(1.5f, 0.5f, -1), vec3(0.5f, 1.5f, -1), vec3(1.0f, 1.0f, 2)));
}

TEST(VoxelOverlap, AnEdgeOnlyOverlapCounts) {
  // The triangle's edge lies along the box's edge y = 0, z = 0; the triangle leans away from it.
  EXPECT_TRUE(overlaps(vec3(0.2f, 0, 0), vec3(0.8f, 0, 0), vec3(0.5f, -1, -1)));
}

// A box mesh filling an n³ grid exactly: its faces lie on the grid's faces, so the voxels it
// touches are the outer layer, n³ − (n − 2)³ = 6n² − 12n + 8.
TEST(VoxelOverlap, AGridFillingBoxTouchesItsShell) {
  Scene scene;
  scene.objects.push_back({.name = "box", .shape = Shape::box, .size = {2, 2, 2}});
  for (const int n : {2, 3, 8, 16}) {
    const std::vector<Triangle> triangles = world_triangles(scene, 0);
    const std::vector<uint8_t> voxels = voxelize_on_cpu(grid_corners(triangles, grid_around(triangles, n)), n);
    EXPECT_EQ(std::accumulate(voxels.begin(), voxels.end(), 0), 6 * n * n - 12 * n + 8) << "n " << n;
  }
}

}  // namespace
}  // namespace volgraph::voxels
