#include "passes/voxels/marching_cubes.h"

#include <algorithm>

#include "passes/voxels/marching_cubes_tables.h"

namespace volgraph::voxels {
namespace {

using marching_cubes_tables::kCubeCorner;
using marching_cubes_tables::kEdgeCorners;

struct FieldGrid {
  const std::vector<float>& values;
  int points;  // along each axis

  size_t index(glm::ivec3 p) const { return (size_t(p.z) * points + size_t(p.y)) * points + size_t(p.x); }
  float at(glm::ivec3 p) const { return values[index(p)]; }

  // Central differences, one-sided on the grid's faces.
  glm::vec3 gradient(glm::ivec3 p) const {
    glm::vec3 g;
    for (int axis = 0; axis < 3; ++axis) {
      glm::ivec3 low = p, high = p;
      low[axis] = std::max(p[axis] - 1, 0);
      high[axis] = std::min(p[axis] + 1, points - 1);
      g[axis] = (at(high) - at(low)) / float(high[axis] - low[axis]);
    }
    return g;
  }
};

}  // namespace

SurfaceMesh marching_cubes(const std::vector<float>& field, int cells) {
  const marching_cubes_tables::CaseTables& tables = marching_cubes_tables::case_tables();
  const FieldGrid grid{field, cells + 1};
  SurfaceMesh mesh;
  // The vertex on the edge from grid point p along axis a: edge_vertex[3 · index(p) + a].
  std::vector<int32_t> edge_vertex(3 * field.size(), -1);
  const auto vertex_on = [&](glm::ivec3 a, glm::ivec3 b) {
    const glm::ivec3 low = glm::min(a, b);
    const int axis = a.x != b.x ? 0 : a.y != b.y ? 1 : 2;
    int32_t& vertex = edge_vertex[3 * grid.index(low) + size_t(axis)];
    if (vertex >= 0) return uint32_t(vertex);
    const float fa = grid.at(a), fb = grid.at(b);
    const float t = fa / (fa - fb);  // one is negative, the other not: fa ≠ fb
    vertex = int32_t(mesh.positions.size());
    mesh.positions.push_back(glm::mix(glm::vec3(a), glm::vec3(b), t));
    const glm::vec3 normal = glm::mix(grid.gradient(a), grid.gradient(b), t);
    const float length = glm::length(normal);
    mesh.normals.push_back(length > 0 ? normal / length : glm::vec3(0, 1, 0));
    return uint32_t(vertex);
  };
  for (int z = 0; z < cells; ++z)
    for (int y = 0; y < cells; ++y)
      for (int x = 0; x < cells; ++x) {
        const glm::ivec3 cell(x, y, z);
        const auto corner = [&](int c) { return cell + glm::ivec3(kCubeCorner[size_t(c)][0], kCubeCorner[size_t(c)][1], kCubeCorner[size_t(c)][2]); };
        int mask = 0;
        for (int c = 0; c < 8; ++c) mask |= int(grid.at(corner(c)) < 0.0f) << c;
        for (const int8_t edge : tables.triangles[size_t(mask)]) {
          if (edge < 0) break;
          mesh.indices.push_back(vertex_on(corner(kEdgeCorners[size_t(edge)][0]), corner(kEdgeCorners[size_t(edge)][1])));
        }
      }
  return mesh;
}

std::vector<float> surface_vertices(const SurfaceMesh& mesh, glm::vec3 origin, float voxel_side) {
  std::vector<float> vertices;
  vertices.reserve(mesh.positions.size() * kSurfaceVertexFloats);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 p = origin + voxel_side * mesh.positions[v], n = mesh.normals[v];
    vertices.insert(vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
  }
  return vertices;
}

}  // namespace volgraph::voxels
