// Triangle meshes of the scene's primitive shapes, in object space (DESIGN.md: plane of
// x and z extent `size`, normal +Y; box of edges `size`; sphere of radius size[0]),
// counter-clockwise seen from outside, with texture coordinates (each face of a box and
// the plane span the image once; spheres map it by latitude and longitude).
#pragma once

#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"

namespace volgraph::plumbing {

// Vertex layout of every mesh the scene passes draw (glTF ones too): position xyz,
// normal xyz, texture coordinate uv, as floats.
constexpr uint32_t kMeshVertexFloats = 8;

struct Mesh {
  std::vector<float> vertices;  // kMeshVertexFloats per vertex
  std::vector<uint32_t> indices;
};

Mesh primitive_mesh(Shape shape, const Vec3& size);

}  // namespace volgraph::plumbing
