// A voxel grid as a mesh of cube faces (RTR4 13.10): the faces between two solid voxels culled,
// then the rest merged greedily into larger rectangles per slice and face direction.
//
// Input: an occupancy grid of n³ voxels, x fastest, then y, then z (voxelize_on_cpu's layout),
// non-zero = solid. Coordinates are voxel units: voxel (x, y, z) is the unit cube [x, x+1]×….
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace volgraph::voxels {

// An axis-aligned rectangle on a voxel face plane: `corner` its least corner, `size` its
// extent (0 along the normal's axis), `normal` the outward unit axis (±x, ±y, ±z).
struct FaceQuad {
  glm::ivec3 corner;
  glm::ivec3 size;
  glm::ivec3 normal;
};

// The number of voxel faces the quad covers (its area in voxel faces).
int64_t face_count(const FaceQuad& quad);

// One unit quad per face of a solid voxel whose neighbour across it is empty or outside the grid.
std::vector<FaceQuad> culled_faces(const std::vector<uint8_t>& solid, int resolution);

// The culled faces merged per slice and direction by greedy meshing: sweep the slice's 2D mask
// of exposed faces, grow a rectangle along u then along v, clear it, repeat. Covers exactly the
// culled faces, each once.
std::vector<FaceQuad> greedy_faces(const std::vector<uint8_t>& solid, int resolution);

// Floats per vertex of face_triangles: the world position (m) and the outward unit normal.
constexpr uint32_t kFaceVertexFloats = 6;

// Quads as the rasterizer draws them (voxel_render's faces variant).
struct FaceTriangles {
  std::vector<float> vertices;    // four a quad, kFaceVertexFloats each
  std::vector<uint32_t> indices;  // two triangles a quad, counter-clockwise seen from the normal's side
};

// The quads in the world: voxel units carried by the grid's placement, world = origin + side · p.
FaceTriangles face_triangles(const std::vector<FaceQuad>& quads, glm::vec3 origin, float voxel_side);

}  // namespace volgraph::voxels
