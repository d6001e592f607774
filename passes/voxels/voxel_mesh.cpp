#include "passes/voxels/voxel_mesh.h"

#include <algorithm>

#include "passes/plumbing/gltf.h"
#include "passes/plumbing/meshes.h"
#include "passes/voxels/voxel_overlap.h"
#include "physics/camera.h"

namespace volgraph::voxels {
namespace {

void append_mesh(const std::vector<float>& vertices, const std::vector<uint32_t>& indices, const physics::Mat4& model,
                 std::vector<Triangle>& out) {
  const auto world = [&](uint32_t v) {
    const float* p = &vertices[size_t(v) * plumbing::kMeshVertexFloats];
    return physics::transform_point(model, {p[0], p[1], p[2]});
  };
  for (size_t t = 0; t + 2 < indices.size(); t += 3) out.push_back({world(indices[t]), world(indices[t + 1]), world(indices[t + 2])});
}

}  // namespace

std::vector<Triangle> world_triangles(const Scene& scene, size_t index) {
  const Object& object = scene.objects.at(index);
  const physics::Mat4 model = physics::model_matrix(object.transform);
  std::vector<Triangle> triangles;
  if (object.shape == Shape::gltf) {
    for (const plumbing::GltfPrimitive& p : plumbing::load_gltf(object.file).primitives) append_mesh(p.vertices, p.indices, model, triangles);
    return triangles;
  }
  const plumbing::Mesh mesh = plumbing::primitive_mesh(object.shape, object.size);
  append_mesh(mesh.vertices, mesh.indices, model, triangles);
  return triangles;
}

gpu::VoxelGrid grid_around(const std::vector<Triangle>& triangles, int resolution) {
  Vec3 low{1e30, 1e30, 1e30}, high{-1e30, -1e30, -1e30};
  for (const Triangle& t : triangles)
    for (const Vec3& p : t)
      for (size_t k = 0; k < 3; ++k) low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
  if (triangles.empty()) low = high = Vec3{0, 0, 0};
  const double side = std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2], 1e-6});
  gpu::VoxelGrid grid{};
  for (size_t k = 0; k < 3; ++k) grid.origin[k] = float(0.5 * (low[k] + high[k]) - 0.5 * side);
  grid.origin[3] = float(side / resolution);
  grid.resolution[0] = resolution;
  return grid;
}

std::vector<float> grid_corners(const std::vector<Triangle>& triangles, const gpu::VoxelGrid& grid) {
  std::vector<float> corners;
  corners.reserve(triangles.size() * 12);
  for (const Triangle& t : triangles)
    for (const Vec3& p : t) {
      for (size_t k = 0; k < 3; ++k) corners.push_back(float((p[k] - double(grid.origin[k])) / double(grid.origin[3])));
      corners.push_back(0.0f);
    }
  return corners;
}

std::vector<uint8_t> voxelize_on_cpu(const std::vector<float>& corners, int resolution) {
  const int n = resolution;
  std::vector<uint8_t> voxels(size_t(n) * n * n, 0);
  for (size_t t = 0; t + 12 <= corners.size(); t += 12) {
    const glm::vec3 a(corners[t], corners[t + 1], corners[t + 2]), b(corners[t + 4], corners[t + 5], corners[t + 6]),
        c(corners[t + 8], corners[t + 9], corners[t + 10]);
    // The voxels of the triangle's bounding box (one more each side: touching counts), clamped to the grid.
    const glm::ivec3 first = glm::clamp(glm::ivec3(glm::floor(glm::min(glm::min(a, b), c))) - 1, 0, n - 1);
    const glm::ivec3 last = glm::clamp(glm::ivec3(glm::floor(glm::max(glm::max(a, b), c))) + 1, 0, n - 1);
    for (int z = first.z; z <= last.z; ++z)
      for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x)
          if (overlap::voxel_overlaps(glm::ivec3(x, y, z), a, b, c)) voxels[(size_t(z) * n + y) * n + x] = 1;
  }
  return voxels;
}

}  // namespace volgraph::voxels
