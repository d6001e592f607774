// glTF 2.0 models (tinygltf) as triangle lists for the passes that rasterise the scene:
// every triangle primitive of the default scene, node transforms applied, with its
// material's base colour and emission factors. Textures are not read yet: a primitive
// says whether its material has them.
#pragma once

#include <string>
#include <vector>

#include "graph/scene/scene.h"

namespace volgraph::shading {

struct GltfPrimitive {
  std::vector<float> vertices;  // position xyz, normal xyz, in the model's space
  std::vector<uint32_t> indices;
  Vec3 base_color{1, 1, 1};  // linear
  Vec3 emissive{0, 0, 0};    // linear radiance factor
  bool base_color_texture = false;
  bool emissive_texture = false;
};

struct GltfModel {
  std::vector<GltfPrimitive> primitives;
  size_t triangle_count() const;
};

// Throws std::runtime_error with what is wrong with the file.
GltfModel load_gltf(const std::string& path);

}  // namespace volgraph::shading
