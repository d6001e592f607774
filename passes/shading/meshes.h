// Triangle meshes of the scene's primitive shapes, in object space (DESIGN.md: plane of
// x and z extent `size`, normal +Y; box of edges `size`; sphere of radius size[0]),
// counter-clockwise seen from outside.
#pragma once

#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"

namespace volgraph::shading {

struct Mesh {
  std::vector<float> vertices;  // position xyz, normal xyz
  std::vector<uint32_t> indices;
};

Mesh primitive_mesh(Shape shape, const Vec3& size);

}  // namespace volgraph::shading
