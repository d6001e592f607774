// Marching cubes' case tables (Lorensen & Cline 1987), in Bourke's numbering of corners and
// edges: corner i at kCubeCorner[i], edge e between kEdgeCorners[e]; case = Σ 2^i over the
// corners inside (field < iso).
//
// The tables are derived, not typed in: on each cube face the contour segments cut off the
// inside corners one run at a time (diagonal inside corners on a face stay separate), oriented
// so that the inside is on one side; the segments chain into closed loops across the faces, and
// each loop is fanned into triangles. A face's segments depend only on its four corners, so two
// cells sharing a face agree on it: the surface is closed and consistently wound (outward, toward
// the positive side, counter-clockwise seen from outside).
#pragma once

#include <array>
#include <cstdint>

namespace volgraph::voxels::marching_cubes_tables {

inline constexpr std::array<std::array<int, 3>, 8> kCubeCorner{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
inline constexpr std::array<std::array<int, 2>, 12> kEdgeCorners{
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

// At most this many triangles in one cube.
inline constexpr int kMaxCaseTriangles = 5;

struct CaseTables {
  std::array<uint16_t, 256> edges;  // bit e: edge e crosses the surface
  // Three edges a triangle, -1 after the last.
  std::array<std::array<int8_t, 3 * kMaxCaseTriangles + 1>, 256> triangles;
};

const CaseTables& case_tables();

}  // namespace volgraph::voxels::marching_cubes_tables
