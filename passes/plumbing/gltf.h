// glTF 2.0 models (tinygltf) as triangle lists for the passes that rasterise the scene:
// every triangle primitive of the default scene, node transforms applied, with its
// material's base colour and emission (factors and textures). Images are checked when
// the file is loaded and kept encoded; passes that sample them decode them
// (passes/plumbing/textures.h), so a pass that only needs geometry pays nothing for them.
#pragma once

#include <string>
#include <vector>

#include "graph/scene/scene.h"
#include "passes/plumbing/textures.h"

namespace volgraph::plumbing {

// A material's texture: an image of the model and how it wraps; image −1: none.
struct GltfTexture {
  int image = -1;
  SamplerWrap wrap;
  explicit operator bool() const { return image >= 0; }
};

struct GltfPrimitive {
  std::vector<float> vertices;  // position xyz, normal xyz, texture coordinate uv, in the model's space
  std::vector<uint32_t> indices;
  Vec3 base_color{1, 1, 1};  // linear
  Vec3 emissive{0, 0, 0};    // linear radiance factor
  GltfTexture base_color_texture;  // sRGB, multiplies base_color
  GltfTexture emissive_texture;    // sRGB, multiplies emissive
  // alphaMode, alphaCutoff and baseColorFactor's alpha (the base colour texture's alpha
  // multiplies it); KHR_materials_transmission, _ior and _volume, the volume's thickness
  // carried into the scene's metres by the node's scale (thicknessFactor is in the mesh's
  // space, attenuationDistance in the world's). thicknessFactor 0 is thin-walled; above 0
  // the volume is solid, its thickness the estimate where no back faces are measured.
  Translucency translucency;
  GltfTexture transmission_texture;  // linear, its red channel multiplies transmission
  GltfTexture thickness_texture;     // linear, its green channel multiplies thickness
};

struct GltfImage {
  std::string name;              // for labels and messages
  std::vector<uint8_t> encoded;  // PNG or JPEG bytes, as in the file
  Rgba8Image decode() const { return decode_image(encoded.data(), encoded.size(), name); }
};

struct GltfModel {
  std::vector<GltfPrimitive> primitives;
  std::vector<GltfImage> images;
  // What the file uses that volgraph does not render, each once, e.g.
  // "KHR_materials_transmission (drawn opaque)"; empty when everything is drawn as specified.
  std::vector<std::string> ignored;
  size_t triangle_count() const;
};

// Throws std::runtime_error with what is wrong with the file, or naming the extension when
// the file requires one volgraph does not support (glTF 2.0 §3.12: a loader must refuse it).
GltfModel load_gltf(const std::string& path);

// The registry's scene annotator (PassRegistry::set_scene_annotator): marks each glTF
// object whose file has a translucent primitive (Object::translucent_in_file); files that
// do not load are left unmarked (the scene pass's checks report them).
void mark_translucent_gltf_objects(Scene& scene);

}  // namespace volgraph::plumbing
