// Culled and greedily merged cube-face meshes of a voxel grid (RTR4 13.10).
#include "passes/voxels/voxel_faces.h"

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

}  // namespace volgraph::voxels
