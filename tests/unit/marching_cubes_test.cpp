// Marching cubes (passes/voxels/marching_cubes.h): the derived case tables against the cube's
// combinatorics; an analytic sphere's field at 32³ meshed: vertices on the sphere, normals
// radial, the mesh closed (every edge in exactly two triangles) and wound outward.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "passes/voxels/marching_cubes.h"
#include "passes/voxels/marching_cubes_tables.h"

namespace volgraph::voxels {
namespace {

// Bit e of the edge table is set exactly when edge e's corners differ; the triangles use exactly
// those edges; the empty and full cubes have none; one corner in or out gives one triangle.
TEST(MarchingCubes, CaseTablesFollowTheCube) {
  const marching_cubes_tables::CaseTables& t = marching_cubes_tables::case_tables();
  int most = 0;
  for (int mask = 0; mask < 256; ++mask) {
    uint16_t used = 0;
    int count = 0;
    for (const int8_t e : t.triangles[size_t(mask)]) {
      if (e < 0) break;
      used |= uint16_t(1u << e), ++count;
    }
    EXPECT_EQ(used, t.edges[size_t(mask)]) << "case " << mask;
    EXPECT_EQ(count % 3, 0);
    most = std::max(most, count / 3);
  }
  EXPECT_EQ(t.triangles[0][0], -1);
  EXPECT_EQ(t.triangles[255][0], -1);
  for (int corner = 0; corner < 8; ++corner) {
    EXPECT_EQ(t.triangles[size_t(1 << corner)][3], -1);
    EXPECT_EQ(t.triangles[size_t(255 ^ (1 << corner))][3], -1);
  }
  std::printf("at most %d triangles a cube\n", most);
}

struct SphereMesh {
  glm::vec3 centre;
  float radius;
  SurfaceMesh mesh;
};

SphereMesh sphere_mesh(int n) {
  const glm::vec3 centre(15.7f, 16.2f, 16.35f);
  const float radius = 11.3f;
  std::vector<float> field;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) field.push_back(glm::length(glm::vec3(i, j, k) - centre) - radius);
  return {centre, radius, marching_cubes(field, n)};
}

// Measured: vertices within 0.0110 voxel of the sphere, normals within 0.101° of radial.
TEST(MarchingCubes, SphereVerticesOnTheSphereNormalsRadial) {
  const SphereMesh s = sphere_mesh(32);
  ASSERT_GT(s.mesh.positions.size(), 1000u);
  double worst_distance = 0, worst_degrees = 0;
  for (size_t v = 0; v < s.mesh.positions.size(); ++v) {
    const glm::vec3 radial = s.mesh.positions[v] - s.centre;
    worst_distance = std::max(worst_distance, std::abs(double(glm::length(radial)) - s.radius));
    const double cosine = std::min(1.0, double(glm::dot(glm::normalize(radial), s.mesh.normals[v])));
    worst_degrees = std::max(worst_degrees, std::acos(cosine) * 180 / M_PI);
  }
  std::printf("sphere r %.1f at 32³: %zu vertices, %zu triangles; worst |‖p − c‖ − r| %.4f voxel, normal %.3f° off radial\n", s.radius,
              s.mesh.positions.size(), s.mesh.indices.size() / 3, worst_distance, worst_degrees);
  EXPECT_LE(worst_distance, 0.02);
  EXPECT_LE(worst_degrees, 1.0);
}

// Closed: every directed edge once and its reverse once (so every edge in exactly two
// triangles, wound consistently); outward: each triangle's normal points away from the centre.
TEST(MarchingCubes, SphereMeshClosedAndWoundOutward) {
  const SphereMesh s = sphere_mesh(32);
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  int inward = 0;
  const std::vector<uint32_t>& ix = s.mesh.indices;
  for (size_t t = 0; t + 2 < ix.size(); t += 3) {
    for (int k = 0; k < 3; ++k) ++directed[{ix[t + size_t(k)], ix[t + size_t((k + 1) % 3)]}];
    const glm::vec3 a = s.mesh.positions[ix[t]], b = s.mesh.positions[ix[t + 1]], c = s.mesh.positions[ix[t + 2]];
    inward += glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - s.centre) <= 0;
  }
  int unmatched = 0;
  for (const auto& [edge, count] : directed) unmatched += count != 1 || directed.count({edge.second, edge.first}) == 0 ||
                                                          directed.at({edge.second, edge.first}) != 1;
  std::printf("%zu directed edges, %d without exactly one reverse twin; %d triangles wound inward\n", directed.size(), unmatched, inward);
  EXPECT_EQ(unmatched, 0);
  EXPECT_EQ(inward, 0);
  // Euler characteristic of a sphere: V − E + F = 2.
  EXPECT_EQ(int64_t(s.mesh.positions.size()) - int64_t(directed.size() / 2) + int64_t(ix.size() / 3), 2);
}

}  // namespace
}  // namespace volgraph::voxels
