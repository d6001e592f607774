// A mesh's signed distance on the corners of voxelize's grid: the exact distance to the nearest
// triangle (Ericson, Real-Time Collision Detection 5.1.5, closest point on a triangle), negative
// inside. Inside by the signed crossings of the grid line through the point along +x (the
// winding number of a closed mesh); a line that grazes an edge or vertex, or whose crossings do
// not cancel (an open mesh), falls back to the generalized winding number (Jacobson et al. 2013)
// at each of its points.
//
// Coordinates are voxelize's grid coordinates (voxel_mesh.h grid_corners: one voxel a unit
// cube), so the field is in voxel units.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace volgraph::voxels {

// The point of triangle abc nearest p (Ericson 5.1.5: Voronoi regions of vertices, edges, face).
glm::dvec3 closest_point_on_triangle(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c);

// Σ Ω(p, triangle) / 4π over the triangles (Jacobson et al. 2013 eq. 2; Ω by Van Oosterom &
// Strackee 1983): 1 inside a closed mesh wound counter-clockwise seen from outside, 0 outside.
// `corners`: three xyzw corners a triangle, as grid_corners gives them.
double generalized_winding_number(glm::dvec3 p, const std::vector<float>& corners);

// The field on the (n + 1)³ grid points, x fastest, then y, then z; point (i, j, k) at (i, j, k).
struct SignedDistanceField {
  int cells = 0;                // n: the grid's voxels along each axis
  std::vector<float> distance;  // voxel units, negative inside
  int64_t fallback_lines = 0;   // grid lines whose sign came from the generalized winding number
  int64_t lines = 0;            // all grid lines, (n + 1)²

  float at(int i, int j, int k) const { return distance[(size_t(k) * (cells + 1) + size_t(j)) * (cells + 1) + size_t(i)]; }
};

SignedDistanceField signed_distance_on_grid(const std::vector<float>& corners, int cells);

}  // namespace volgraph::voxels
