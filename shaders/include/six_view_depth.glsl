// voxelize, variant six_view_depth (passes/voxels/voxelize.cpp): Karabassi et al. 1999's six
// orthographic depth views of an object over its voxel grid, one text for the views' vertex
// shader and the compute step that reads them. View v (0…5) looks along axis v / 2 (x, y, z),
// from the grid's low side when v is even (+ view), from its high side when odd (− view);
// its image's u and v are the next two axes in turn, so texel (i, j) of every view along one
// axis lies on the line through the centres of the voxels with those two coordinates.
#ifndef VOLGRAPH_SIX_VIEW_DEPTH_GLSL
#define VOLGRAPH_SIX_VIEW_DEPTH_GLSL

// A point's depth in a view along its axis, `along` its place along that axis as a fraction of
// the grid (0 low side, 1 high side), `minus` for the − view: the grid's box spans depths
// ¼ … ¾, so faces on the grid's sides, a rounding outside it, are not clipped away.
float six_view_depth_of(float along, bool minus) { return 0.25 + 0.5 * (minus ? 1.0 - along : along); }

// A point in grid coordinates (voxels, [0, n]³) in view v's clip space: x, y over the image
// (NDC +y up, row 0 at the top), the depth as above.
vec4 six_view_clip(vec3 grid_point, int view, float resolution) {
  const int axis = view / 2;
  const vec3 p = grid_point / resolution;
  return vec4(2.0 * p[(axis + 1) % 3] - 1.0, 1.0 - 2.0 * p[(axis + 2) % 3], six_view_depth_of(p[axis], view % 2 == 1), 1.0);
}

// The texel of the views along `axis` on the line through voxel `voxel`'s centre.
ivec2 six_view_texel(ivec3 voxel, int axis) { return ivec2(voxel[(axis + 1) % 3], voxel[(axis + 2) % 3]); }

// Karabassi et al. 1999: along one axis a centre (`along` as above) is inside when it lies
// behind the nearest surface the + view sees and behind the nearest the − view sees, each in
// its own view's depth; nothing drawn (depth 1, the clear) leaves it outside.
bool six_view_inside_along(float along, float plus_depth, float minus_depth) {
  return plus_depth < six_view_depth_of(along, false) && minus_depth < six_view_depth_of(along, true);
}

#endif  // VOLGRAPH_SIX_VIEW_DEPTH_GLSL
