#version 450
#extension GL_GOOGLE_include_directive : require
// light_volume, height_field variant: the shadow volume as Billeter, Sintorn, Assarsson
// 2010 (§4) build it — one vertex per grid cell, at the cell's centre and depth
// (light_volume_cells.frag; the border's vertices moved out to the map's edges), joined
// into a height field that the rasterizer interpolates between cells; walls along the
// map's four edges down to its far plane; a far cap. Vertex i < N²: cell (i % N, i / N)
// on the surface; then 4N vertices on the far plane under the top, bottom, left and right
// rows of cells. The triangles (an index buffer, passes/fog/light_volume.cpp) wind so
// that normals point out of the shadowed region in light clip space.
#include "include/light_volume.glsl"

layout(set = 0, binding = 0) uniform Params { LightVolumeParams p; } params;
layout(set = 0, binding = 1) uniform texture2D cells;
layout(set = 0, binding = 2) uniform texture2D light_frame;
layout(set = 0, binding = 3) uniform sampler nearest;

// NDC of node (k, l): the cell's centre, the border's on the map's edges.
vec2 node_ndc(ivec2 node, int n) {
  const vec2 centre = (2.0 * vec2(node) + 1.0) / float(n) - 1.0;
  const vec2 x = vec2(node.x == 0 ? -1.0 : node.x == n - 1 ? 1.0 : centre.x, node.y == 0 ? -1.0 : node.y == n - 1 ? 1.0 : centre.y);
  return vec2(x.x, -x.y);  // row 0 at the top of the map: NDC y = +1
}

void main() {
  const int n = params.p.sizes.x, v = gl_VertexIndex;
  ivec2 node;
  float z = 1.0;
  if (v < n * n) {
    node = ivec2(v % n, v / n);
    z = texelFetch(sampler2D(cells, nearest), node, 0).r;
  } else {
    const int edge = (v - n * n) / n, i = (v - n * n) % n;
    node = edge == 0 ? ivec2(i, 0) : edge == 1 ? ivec2(i, n - 1) : edge == 2 ? ivec2(0, i) : ivec2(n - 1, i);
  }
  const vec4 world = light_clip_to_world(light_frame, nearest) * vec4(node_ndc(node, n), z, 1.0);
  gl_Position = params.p.camera_clip * vec4(world.xyz / world.w, 1.0);
}
