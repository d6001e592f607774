// The conservative triangle–voxel test of voxelize (passes/voxels/voxelize.cpp): Akenine-Möller
// 2001's triangle–box overlap by the separating axis theorem (RTR4 22.12), in the grid's
// coordinates (one voxel a unit cube, voxel (i, j, k) the box [i, i+1] × [j, j+1] × [k, k+1]).
// Touching counts as overlapping (closed boxes, closed triangles).
//
// ONE TEXT FOR BOTH SIDES: GLSL includes this file, C++ includes it inside a namespace with
// GLM's types (passes/voxels/voxel_overlap.h), so the CPU twin voxelizes bit for bit as the
// GPU does. Every product and sum is written out in one order and, in GLSL, `precise` (no
// fused multiply-add), so both sides round alike.
#ifndef VOLGRAPH_VOXEL_OVERLAP_H
#define VOLGRAPH_VOXEL_OVERLAP_H

#include "voxel_fn.h"

#ifdef __cplusplus
#define VOXEL_PRECISE
#else
#define VOXEL_PRECISE precise
#endif

VOXEL_FN float voxel_dot(vec3 a, vec3 b) {
  VOXEL_PRECISE float d = a.x * b.x + a.y * b.y + a.z * b.z;
  return d;
}

VOXEL_FN vec3 voxel_cross(vec3 a, vec3 b) {
  VOXEL_PRECISE vec3 c = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return c;
}

// Whether `axis` separates the triangle (v0, v1, v2, relative to the box's centre) from the
// box of half-size `half_side`: the triangle's projection [min p, max p] misses [−r, r], r the
// box's projected radius (RTR4 22.12: r = h Σ |a_i| for a cube of half-size h). A zero axis separates nothing.
VOXEL_FN bool voxel_separates(vec3 axis, vec3 v0, vec3 v1, vec3 v2, float half_side) {
  VOXEL_PRECISE float p0 = voxel_dot(axis, v0);
  VOXEL_PRECISE float p1 = voxel_dot(axis, v1);
  VOXEL_PRECISE float p2 = voxel_dot(axis, v2);
  VOXEL_PRECISE float r = half_side * (abs(axis.x) + abs(axis.y) + abs(axis.z));
  return min(min(p0, p1), p2) > r || max(max(p0, p1), p2) < -r;
}

// Whether box edge direction u crossed with any triangle edge separates them.
VOXEL_FN bool voxel_edges_separate(vec3 u, vec3 e0, vec3 e1, vec3 e2, vec3 v0, vec3 v1, vec3 v2, float half_side) {
  return voxel_separates(voxel_cross(u, e0), v0, v1, v2, half_side) || voxel_separates(voxel_cross(u, e1), v0, v1, v2, half_side) ||
         voxel_separates(voxel_cross(u, e2), v0, v1, v2, half_side);
}

// Akenine-Möller's test (RTR4 22.12): the three box normals (the bounding boxes), the
// triangle's normal, and the nine cross products of the box's and the triangle's edges;
// overlapping when none of the 13 axes separates them.
VOXEL_FN bool voxel_triangle_overlaps(vec3 box_center, float half_side, vec3 a, vec3 b, vec3 c) {
  VOXEL_PRECISE vec3 v0 = a - box_center;
  VOXEL_PRECISE vec3 v1 = b - box_center;
  VOXEL_PRECISE vec3 v2 = c - box_center;
  // The box's normals: the bounding boxes overlap.
  if (min(min(v0.x, v1.x), v2.x) > half_side || max(max(v0.x, v1.x), v2.x) < -half_side) return false;
  if (min(min(v0.y, v1.y), v2.y) > half_side || max(max(v0.y, v1.y), v2.y) < -half_side) return false;
  if (min(min(v0.z, v1.z), v2.z) > half_side || max(max(v0.z, v1.z), v2.z) < -half_side) return false;
  VOXEL_PRECISE vec3 e0 = v1 - v0;
  VOXEL_PRECISE vec3 e1 = v2 - v1;
  VOXEL_PRECISE vec3 e2 = v0 - v2;
  // The triangle's plane.
  if (voxel_separates(voxel_cross(e0, e1), v0, v1, v2, half_side)) return false;
  // The nine axes: each box edge direction × each triangle edge.
  if (voxel_edges_separate(vec3(1.0f, 0.0f, 0.0f), e0, e1, e2, v0, v1, v2, half_side)) return false;
  if (voxel_edges_separate(vec3(0.0f, 1.0f, 0.0f), e0, e1, e2, v0, v1, v2, half_side)) return false;
  if (voxel_edges_separate(vec3(0.0f, 0.0f, 1.0f), e0, e1, e2, v0, v1, v2, half_side)) return false;
  return true;
}

// Voxel `voxel` (integer coordinates) against the triangle (a, b, c) in grid coordinates.
VOXEL_FN bool voxel_overlaps(ivec3 voxel, vec3 a, vec3 b, vec3 c) {
  return voxel_triangle_overlaps(vec3(voxel) + vec3(0.5f), 0.5f, a, b, c);
}

#endif  // VOLGRAPH_VOXEL_OVERLAP_H
