#version 450
#extension GL_GOOGLE_include_directive : require
// light_volume, the shadow volume's faces (Billeter, Sintorn, Assarsson 2010, §4: a grid
// over the shadow map, displaced by its depths): the region the shadow map's hard lookup
// calls shadowed is, per cell of the grid, the light's rays through the cell between the
// cell's depth (light_volume_cells.frag) and the map's far plane. Each cell emits, in its
// light clip space (x, y over the map, z its normalised depth), a cap where the shadow
// starts, a cap on the far plane, and the walls toward its left and upper neighbours over
// the depths where one is shadowed and the other is not; cells outside the map count as
// unshadowed. Every face winds so that its normal points out of the shadowed region (in
// light clip space; light_frame gives the sign the world adds). Faces with nothing to
// bound (an unshadowed cell's caps, walls between equal depths) are dropped.
// The mesh is watertight for the rasterizer: a wall's vertical edges, on the lines where
// four cells meet, carry a vertex at each of the four cells' depths inside the wall's
// range (a ladder of 3 quads), so no edge ends in the middle of another (T-junctions
// leave cracks that single pixels see through).
// Vertex i: cell i / 48 of the (N + 1)² cells; 0–11 the two caps, 12–47 the two walls,
// 6 vertices (two triangles) per quad.
#include "include/light_volume.glsl"

layout(set = 0, binding = 0) uniform Params { LightVolumeParams p; } params;
layout(set = 0, binding = 1) uniform texture2D cells;
layout(set = 0, binding = 2) uniform texture2D light_frame;
layout(set = 0, binding = 3) uniform sampler nearest;

const int VERTICES_PER_CELL = 48;
const int CAP_VERTICES = 12, WALL_VERTICES = 18;
const int QUAD_CORNER[6] = int[6](0, 1, 2, 0, 2, 3);

// Where cell (i, j)'s shadow starts; 1 (none) outside the grid.
float shadow_start(ivec2 cell, int n) {
  if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, ivec2(n)))) return 1.0;
  return texelFetch(sampler2D(cells, nearest), cell, 0).r;
}

// NDC x of the grid's column edge i, y of its row edge j (row 0 at the top of the map).
vec2 grid_edge(ivec2 edge, int n) { return vec2(2.0 * float(edge.x) / float(n) - 1.0, 1.0 - 2.0 * float(edge.y) / float(n)); }

// Corner k (0–3) of cap `far` (false: where the shadow starts, normal −z toward the
// light; true: the far plane, normal +z) of cell `cell`; false when the cell is unshadowed.
bool cap_corner(ivec2 cell, bool far, int k, int n, out vec3 corner) {
  const float start = shadow_start(cell, n);
  if (start >= 1.0) return false;
  const vec2 lo = grid_edge(ivec2(cell.x, cell.y + 1), n), hi = grid_edge(ivec2(cell.x + 1, cell.y), n);  // (x0, y_bottom), (x1, y_top)
  const vec2 toward_light[4] = vec2[4](vec2(lo.x, lo.y), vec2(lo.x, hi.y), vec2(hi.x, hi.y), vec2(hi.x, lo.y));
  const vec2 away[4] = vec2[4](vec2(lo.x, lo.y), vec2(hi.x, lo.y), vec2(hi.x, hi.y), vec2(lo.x, hi.y));
  corner = far ? vec3(away[k], 1.0) : vec3(toward_light[k], start);
  return true;
}

// Level `level` (0–3) of a wall's edge from za to zb on a line where two other cells
// start at o1 and o2: za, the others' depths inside the wall's range in order, zb.
float edge_level(float za, float zb, float o1, float o2, int level) {
  const float lo = min(za, zb), hi = max(za, zb);
  const float c1 = clamp(o1, lo, hi), c2 = clamp(o2, lo, hi);
  const vec4 levels = za <= zb ? vec4(za, min(c1, c2), max(c1, c2), zb) : vec4(za, max(c1, c2), min(c1, c2), zb);
  return levels[level];
}

// Corner k of rung quad `rung` (0–2) of the wall between `cell` and its left (`left`) or
// upper neighbour, which starts at za (this cell at zb). Corners 0 and 3 lie on the
// wall's first vertical edge, 1 and 2 on its second; the quad's normal is ±x (±y) by
// the sign of zb − za, out of whichever side is shadowed there.
bool wall_corner(ivec2 cell, bool left, int rung, int k, int n, out vec3 corner) {
  const ivec2 across = left ? ivec2(1, 0) : ivec2(0, 1), along = left ? ivec2(0, 1) : ivec2(1, 0);
  const float za = shadow_start(cell - across, n), zb = shadow_start(cell, n);
  if (za == zb || (left ? cell.y : cell.x) >= n) return false;
  // The wall's vertical edges: the left wall's at its bottom (y_bottom, the next row) then
  // top, the upper wall's at its left (x0, the previous column) then right; the two
  // other cells meeting on each.
  const bool second = k == 1 || k == 2;
  const ivec2 other = second != left ? cell + along : cell - along;
  const int level = rung + (k >= 2 ? 1 : 0);
  const float z = edge_level(za, zb, shadow_start(other - across, n), shadow_start(other, n), level);
  const vec2 lo = grid_edge(ivec2(cell.x, cell.y + 1), n), hi = grid_edge(ivec2(cell.x + 1, cell.y), n);
  corner = left ? vec3(lo.x, second ? hi.y : lo.y, z) : vec3(second ? hi.x : lo.x, hi.y, z);
  return true;
}

bool face_corner(ivec2 cell, int within, int n, out vec3 corner) {
  const int k = QUAD_CORNER[within % 6];
  if (within < CAP_VERTICES) return cap_corner(cell, within >= 6, k, n, corner);
  const int wall = (within - CAP_VERTICES) / WALL_VERTICES, rung = ((within - CAP_VERTICES) % WALL_VERTICES) / 6;
  return wall_corner(cell, wall == 0, rung, k, n, corner);
}

void main() {
  const int n = params.p.sizes.x;
  const int index = gl_VertexIndex / VERTICES_PER_CELL;
  const ivec2 cell = ivec2(index % (n + 1), index / (n + 1));
  vec3 corner;
  if (!face_corner(cell, gl_VertexIndex % VERTICES_PER_CELL, n, corner)) {
    gl_Position = vec4(-2.0, -2.0, 0.5, 1.0);  // outside the view: the triangle is dropped
    return;
  }
  const vec4 world = light_clip_to_world(light_frame, nearest) * vec4(corner, 1.0);
  gl_Position = params.p.camera_clip * vec4(world.xyz / world.w, 1.0);
}
