// Culled and greedily merged cube-face meshes of a voxel grid (RTR4 13.10).
#include "passes/voxels/voxel_faces.h"

#include <utility>

namespace volgraph::voxels {
namespace {

bool solid_at(const std::vector<uint8_t>& solid, int n, glm::ivec3 v) {
  if (glm::any(glm::lessThan(v, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(v, glm::ivec3(n)))) return false;
  return solid[(size_t(v.z) * n + v.y) * n + v.x] != 0;
}

// A face direction: the normal's axis and sign, and the two in-plane axes u, v (cyclic after the axis).
struct FaceDirection {
  int axis, u, v;
  int sign;
  glm::ivec3 normal() const { glm::ivec3 n(0); n[axis] = sign; return n; }
};

std::vector<FaceDirection> face_directions() {
  std::vector<FaceDirection> out;
  for (int axis = 0; axis < 3; ++axis)
    for (const int sign : {-1, 1}) out.push_back({axis, (axis + 1) % 3, (axis + 2) % 3, sign});
  return out;
}

// The face of solid voxel `v` facing `d` is drawn when the neighbour across it is empty or outside.
bool face_exposed(const std::vector<uint8_t>& solid, int n, glm::ivec3 v, const FaceDirection& d) {
  return solid_at(solid, n, v) && !solid_at(solid, n, v + d.normal());
}

// The voxel at `layer` along d's axis and (i, j) along its u, v axes.
glm::ivec3 voxel_in_slice(const FaceDirection& d, int layer, int i, int j) {
  glm::ivec3 v;
  v[d.axis] = layer;
  v[d.u] = i;
  v[d.v] = j;
  return v;
}

// The quad over a w × h block of faces of slice `layer` at (i, j): the plane is the voxel's far face for +, near for −.
FaceQuad slice_quad(const FaceDirection& d, int layer, int i, int j, int w, int h) {
  FaceQuad q{voxel_in_slice(d, layer + (d.sign > 0 ? 1 : 0), i, j), glm::ivec3(0), d.normal()};
  q.size[d.u] = w;
  q.size[d.v] = h;
  return q;
}

// Greedy meshing of one slice's mask (n × n, i fastest): rectangles grown along u, then along v.
void merge_mask(std::vector<uint8_t>& mask, int n, const FaceDirection& d, int layer, std::vector<FaceQuad>& out) {
  const auto at = [&](int i, int j) -> uint8_t& { return mask[size_t(j) * n + i]; };
  const auto row_set = [&](int i, int j, int w) {
    for (int k = 0; k < w; ++k)
      if (!at(i + k, j)) return false;
    return true;
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (!at(i, j)) continue;
      int w = 1;
      while (i + w < n && at(i + w, j)) ++w;
      int h = 1;
      while (j + h < n && row_set(i, j + h, w)) ++h;
      for (int b = 0; b < h; ++b)
        for (int a = 0; a < w; ++a) at(i + a, j + b) = 0;
      out.push_back(slice_quad(d, layer, i, j, w, h));
    }
}

}  // namespace

int64_t face_count(const FaceQuad& quad) {
  int64_t area = 1;
  for (int axis = 0; axis < 3; ++axis)
    if (quad.normal[axis] == 0) area *= quad.size[axis];
  return area;
}

std::vector<FaceQuad> culled_faces(const std::vector<uint8_t>& solid, int resolution) {
  std::vector<FaceQuad> out;
  for (const FaceDirection& d : face_directions())
    for (int layer = 0; layer < resolution; ++layer)
      for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i)
          if (face_exposed(solid, resolution, voxel_in_slice(d, layer, i, j), d)) out.push_back(slice_quad(d, layer, i, j, 1, 1));
  return out;
}

std::vector<FaceQuad> greedy_faces(const std::vector<uint8_t>& solid, int resolution) {
  std::vector<FaceQuad> out;
  std::vector<uint8_t> mask(size_t(resolution) * resolution);
  for (const FaceDirection& d : face_directions())
    for (int layer = 0; layer < resolution; ++layer) {
      for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i)
          mask[size_t(j) * resolution + i] = face_exposed(solid, resolution, voxel_in_slice(d, layer, i, j), d);
      merge_mask(mask, resolution, d, layer, out);
    }
  return out;
}

FaceTriangles face_triangles(const std::vector<FaceQuad>& quads, glm::vec3 origin, float voxel_side) {
  FaceTriangles out;
  out.vertices.reserve(quads.size() * 4 * kFaceVertexFloats);
  out.indices.reserve(quads.size() * 6);
  for (const FaceQuad& q : quads) {
    int axis = 0;
    while (q.normal[axis] == 0) ++axis;
    // Along u then v (cyclic after the normal's axis, u × v = +axis) is counter-clockwise seen from +axis.
    glm::ivec3 along_u(0), along_v(0);
    along_u[(axis + 1) % 3] = q.size[(axis + 1) % 3];
    along_v[(axis + 2) % 3] = q.size[(axis + 2) % 3];
    if (q.normal[axis] < 0) std::swap(along_u, along_v);
    const uint32_t first = uint32_t(out.vertices.size() / kFaceVertexFloats);
    for (const glm::ivec3 corner : {q.corner, q.corner + along_u, q.corner + along_u + along_v, q.corner + along_v}) {
      const glm::vec3 p = origin + voxel_side * glm::vec3(corner);
      out.vertices.insert(out.vertices.end(), {p.x, p.y, p.z, float(q.normal.x), float(q.normal.y), float(q.normal.z)});
    }
    out.indices.insert(out.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  return out;
}

}  // namespace volgraph::voxels
