#include "passes/voxels/marching_cubes_tables.h"

#include <stdexcept>
#include <vector>

namespace volgraph::voxels::marching_cubes_tables {
namespace {

// The six faces, four corners each, counter-clockwise seen from outside the cube.
constexpr std::array<std::array<int, 4>, 6> kCubeFaces{{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}}};

int edge_between(int a, int b) {
  for (int e = 0; e < 12; ++e)
    if ((kEdgeCorners[e][0] == a && kEdgeCorners[e][1] == b) || (kEdgeCorners[e][0] == b && kEdgeCorners[e][1] == a)) return e;
  throw std::logic_error("marching cubes: corners not on one edge");
}

// next[e]: the edge the contour goes to from edge e's crossing. On each face, walked
// counter-clockwise from outside, crossings alternate entering and leaving the inside; each
// run of inside corners is cut off by one segment, from its entering crossing to its leaving one.
std::array<int, 12> contour_successors(int inside_mask) {
  std::array<int, 12> next;
  next.fill(-1);
  const auto inside = [&](int corner) { return (inside_mask >> corner & 1) != 0; };
  for (const std::array<int, 4>& face : kCubeFaces) {
    int entering = -1, first_leaving = -1;
    for (int k = 0; k < 4; ++k) {
      const int from = face[size_t(k)], to = face[size_t((k + 1) % 4)];
      if (inside(from) == inside(to)) continue;
      const int edge = edge_between(from, to);
      if (inside(to)) {
        entering = edge;
      } else if (entering >= 0) {
        next[size_t(entering)] = edge;
      } else {
        first_leaving = edge;  // its run began before corner 0 of the walk: closed by the walk's last entering
      }
    }
    if (first_leaving >= 0) next[size_t(entering)] = first_leaving;
  }
  return next;
}

CaseTables derive_case_tables() {
  CaseTables tables{};
  for (int mask = 0; mask < 256; ++mask) {
    uint16_t edges = 0;
    for (int e = 0; e < 12; ++e) edges |= uint16_t(((mask >> kEdgeCorners[e][0] & 1) != (mask >> kEdgeCorners[e][1] & 1)) << e);
    tables.edges[size_t(mask)] = edges;
    const std::array<int, 12> next = contour_successors(mask);
    std::vector<int8_t> triangles;
    std::array<bool, 12> visited{};
    for (int start = 0; start < 12; ++start) {
      if (next[size_t(start)] < 0 || visited[size_t(start)]) continue;
      std::vector<int> loop;
      for (int e = start; !visited[size_t(e)]; e = next[size_t(e)]) visited[size_t(e)] = true, loop.push_back(e);
      for (size_t i = 1; i + 1 < loop.size(); ++i)  // a fan over the loop
        triangles.insert(triangles.end(), {int8_t(loop[0]), int8_t(loop[i]), int8_t(loop[i + 1])});
    }
    if (triangles.size() > 3 * kMaxCaseTriangles) throw std::logic_error("marching cubes: a case needs more triangles than the table holds");
    tables.triangles[size_t(mask)].fill(-1);
    for (size_t i = 0; i < triangles.size(); ++i) tables.triangles[size_t(mask)][i] = triangles[i];
  }
  return tables;
}

}  // namespace

const CaseTables& case_tables() {
  static const CaseTables tables = derive_case_tables();
  return tables;
}

}  // namespace volgraph::voxels::marching_cubes_tables
