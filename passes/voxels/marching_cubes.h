// Marching cubes (Lorensen & Cline 1987) over a field sampled on a grid's (n + 1)³ points at
// iso 0: inside where the field is negative. Vertices on the cube edges by linear interpolation,
// one per crossed edge (welded: shared by every cell around the edge); normals from the field's
// gradient (central differences at the grid points, one-sided on the grid's faces), interpolated
// along the edge as the position is. Triangles counter-clockwise seen from outside (the positive side).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace volgraph::voxels {

struct SurfaceMesh {
  std::vector<glm::vec3> positions;  // grid coordinates (one voxel a unit cube)
  std::vector<glm::vec3> normals;    // unit, outward (the normalized gradient)
  std::vector<uint32_t> indices;     // three a triangle
};

// `field`: (cells + 1)³ samples, x fastest, then y, then z; point (i, j, k) at (i, j, k).
SurfaceMesh marching_cubes(const std::vector<float>& field, int cells);

// Floats per vertex of surface_vertices: the world position (m) and the unit normal (as face_triangles).
constexpr uint32_t kSurfaceVertexFloats = 6;

// The mesh's vertices in the world: world = origin + side · p, normals unchanged.
std::vector<float> surface_vertices(const SurfaceMesh& mesh, glm::vec3 origin, float voxel_side);

}  // namespace volgraph::voxels
