#include "passes/plumbing/gltf.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <sstream>
#include <stdexcept>

#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>

#include "physics/camera.h"

namespace volgraph::plumbing {

using namespace physics;  // the CPU maths these helpers are written in
namespace {

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error(message); }

// The largest value of an unsigned component type (normalised integers map it to 1).
double unsigned_max(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 255.0;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 65535.0;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return 4294967295.0;
    default: return 1.0;
  }
}

// The accessor's elements as doubles (`components` per element), bounds-checked.
std::vector<double> read_accessor(const tinygltf::Model& m, int index, int components) {
  if (index < 0 || size_t(index) >= m.accessors.size()) fail("accessor " + std::to_string(index) + " does not exist");
  const tinygltf::Accessor& a = m.accessors[size_t(index)];
  if (a.bufferView < 0 || size_t(a.bufferView) >= m.bufferViews.size()) fail("accessor " + std::to_string(index) + " has no buffer view");
  const tinygltf::BufferView& view = m.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= m.buffers.size()) fail("buffer view of accessor " + std::to_string(index) + " has no buffer");
  const std::vector<unsigned char>& data = m.buffers[size_t(view.buffer)].data;
  const int count_per = tinygltf::GetNumComponentsInType(uint32_t(a.type));
  const int size = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
  if (count_per != components || size <= 0) fail("accessor " + std::to_string(index) + " has an unexpected type");
  const size_t stride = view.byteStride ? view.byteStride : size_t(size * components);
  const size_t start = view.byteOffset + a.byteOffset;
  if (a.count > 0 && (start + (a.count - 1) * stride + size_t(size * components) > data.size() ||
                      a.byteOffset + (a.count - 1) * stride + size_t(size * components) > view.byteLength)) {
    fail("accessor " + std::to_string(index) + " reads past its buffer");
  }
  std::vector<double> out(a.count * size_t(components));
  for (size_t e = 0; e < a.count; ++e) {
    for (int c = 0; c < components; ++c) {
      const unsigned char* p = data.data() + start + e * stride + size_t(c * size);
      double v = 0;
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); v = f; break; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t u; std::memcpy(&u, p, 4); v = u; break; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { uint16_t u; std::memcpy(&u, p, 2); v = u; break; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: v = *p; break;
        default: fail("accessor " + std::to_string(index) + " has an unsupported component type");
      }
      out[e * size_t(components) + size_t(c)] = a.normalized ? v / unsigned_max(a.componentType) : v;
    }
  }
  return out;
}

Mat4 node_matrix(const tinygltf::Node& n) {
  if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as glTF
  Mat4 t(1), r(1), s(1);
  if (n.translation.size() == 3) t = glm::translate(Mat4(1), glm::make_vec3(n.translation.data()));
  if (n.scale.size() == 3) s = glm::scale(Mat4(1), glm::make_vec3(n.scale.data()));
  if (n.rotation.size() == 4) {  // unit quaternion x, y, z, w
    const std::vector<double>& q = n.rotation;
    r = glm::mat4_cast(glm::dquat(q[3], q[0], q[1], q[2]));  // GLM's quaternion takes w first
  }
  return t * r * s;
}

const tinygltf::Material* material_of(const tinygltf::Model& m, const tinygltf::Primitive& p) {
  return p.material >= 0 && size_t(p.material) < m.materials.size() ? &m.materials[size_t(p.material)] : nullptr;
}

rhi::AddressMode address_mode(int gltf_wrap) {
  switch (gltf_wrap) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return rhi::AddressMode::clamp_to_edge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return rhi::AddressMode::mirror_repeat;
    default: return rhi::AddressMode::repeat;
  }
}

// glTF texture `index` as an image and wrap modes (none for −1).
GltfTexture texture(const tinygltf::Model& m, int index) {
  if (index < 0) return {};
  if (size_t(index) >= m.textures.size()) fail("texture " + std::to_string(index) + " does not exist");
  const tinygltf::Texture& t = m.textures[size_t(index)];
  if (t.source < 0 || size_t(t.source) >= m.images.size()) fail("texture " + std::to_string(index) + " has no image");
  GltfTexture out;
  out.image = t.source;
  if (t.sampler >= 0 && size_t(t.sampler) < m.samplers.size()) {
    out.wrap = {address_mode(m.samplers[size_t(t.sampler)].wrapS), address_mode(m.samplers[size_t(t.sampler)].wrapT)};
  }
  return out;
}

// The texture coordinates the material's textures use (base colour's set, else
// emission's, else 0), as u, v pairs; empty when the primitive has none.
std::vector<double> texture_coordinates(const tinygltf::Model& m, const tinygltf::Primitive& p, size_t vertex_count) {
  int set = 0;
  if (const tinygltf::Material* mat = material_of(m, p)) {
    set = mat->pbrMetallicRoughness.baseColorTexture.index >= 0 ? mat->pbrMetallicRoughness.baseColorTexture.texCoord
                                                                 : mat->emissiveTexture.texCoord;
  }
  const auto found = p.attributes.find("TEXCOORD_" + std::to_string(std::max(set, 0)));
  if (found == p.attributes.end()) return {};
  std::vector<double> uv = read_accessor(m, found->second, 2);
  if (uv.size() != 2 * vertex_count) fail("TEXCOORD and POSITION differ in count");
  return uv;
}

// A number at `key` of an extension's object, or `fallback` when absent or not a number.
double number(const tinygltf::Value& object, const char* key, double fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

// The texture index of a textureInfo at `key` of an extension's object; −1 when absent.
int texture_index(const tinygltf::Value& object, const char* key) {
  if (!object.IsObject() || !object.Has(key)) return -1;
  const tinygltf::Value& info = object.Get(key);
  return info.IsObject() && info.Has("index") && info.Get("index").IsNumber() ? info.Get("index").GetNumberAsInt() : -1;
}

const tinygltf::Value* extension(const tinygltf::Material& mat, const char* name) {
  const auto found = mat.extensions.find(name);
  return found == mat.extensions.end() ? nullptr : &found->second;
}

AlphaMode alpha_mode(const std::string& gltf_mode) {
  if (gltf_mode == "BLEND") return AlphaMode::blend;
  if (gltf_mode == "MASK") return AlphaMode::mask;
  return AlphaMode::opaque;
}

// glTF 2.0's alphaMode, KHR_materials_transmission, _ior, _dispersion and _volume as scene.h's
// Translucency; the volume's thickness carried from the mesh's space into the model's by
// the node's `thickness_scale` (KHR_materials_volume: thicknessFactor is in the mesh's
// space, attenuationDistance in the world's).
void read_translucency(const tinygltf::Model& m, const tinygltf::Material& mat, double thickness_scale, GltfPrimitive& out) {
  Translucency& t = out.translucency;
  const auto& f = mat.pbrMetallicRoughness.baseColorFactor;
  if (f.size() == 4) t.alpha = f[3];
  t.alpha_mode = alpha_mode(mat.alphaMode);
  t.alpha_cutoff = mat.alphaCutoff;
  t.roughness = std::clamp(mat.pbrMetallicRoughness.roughnessFactor, 0.0, 1.0);  // glTF's default: 1
  if (const tinygltf::Value* transmission = extension(mat, "KHR_materials_transmission")) {
    t.transmission = std::clamp(number(*transmission, "transmissionFactor", 0), 0.0, 1.0);
    out.transmission_texture = texture(m, texture_index(*transmission, "transmissionTexture"));
  }
  if (const tinygltf::Value* ior = extension(mat, "KHR_materials_ior")) t.ior = std::clamp(number(*ior, "ior", 1.5), 1.0, 4.0);
  // KHR_materials_dispersion: 20/V_d, ≥ 0 by its schema (a negative one is held at 0, as the other factors are clamped).
  if (const tinygltf::Value* d = extension(mat, "KHR_materials_dispersion")) t.dispersion = std::max(number(*d, "dispersion", 0), 0.0);
  if (const tinygltf::Value* volume = extension(mat, "KHR_materials_volume")) {
    t.thickness = std::max(number(*volume, "thicknessFactor", 0), 0.0) * thickness_scale;
    t.volume = t.thickness > 0 ? VolumeKind::solid : VolumeKind::thin_walled;
    t.attenuation_distance = std::clamp(number(*volume, "attenuationDistance", 1e30), 1e-6, 1e30);
    if (volume->Has("attenuationColor") && volume->Get("attenuationColor").IsArray() && volume->Get("attenuationColor").ArrayLen() == 3) {
      for (int i = 0; i < 3; ++i) t.attenuation_color[size_t(i)] = std::clamp(volume->Get("attenuationColor").Get(i).GetNumberAsDouble(), 0.0, 1.0);
    }
    out.thickness_texture = texture(m, texture_index(*volume, "thicknessTexture"));
  }
}

GltfPrimitive primitive(const tinygltf::Model& m, const tinygltf::Primitive& p, const Mat4& to_model) {
  GltfPrimitive out;
  const auto position = p.attributes.find("POSITION");
  if (position == p.attributes.end()) fail("a primitive has no POSITION");
  const std::vector<double> pos = read_accessor(m, position->second, 3);
  const size_t n = pos.size() / 3;
  std::vector<uint32_t> indices;
  if (p.indices >= 0) {
    for (double i : read_accessor(m, p.indices, 1)) {
      if (i >= double(n)) fail("an index points past the primitive's vertices");
      indices.push_back(uint32_t(i));
    }
  } else {
    for (uint32_t i = 0; i < n; ++i) indices.push_back(i);
  }
  if (indices.size() % 3) fail("a triangle primitive's index count is not a multiple of 3");
  const auto normal = p.attributes.find("NORMAL");
  const std::vector<double> nrm = normal != p.attributes.end() ? read_accessor(m, normal->second, 3) : std::vector<double>{};
  if (!nrm.empty() && nrm.size() != pos.size()) fail("NORMAL and POSITION differ in count");
  const std::vector<double> uv = texture_coordinates(m, p, n);
  const Mat4 carry = normal_matrix(to_model);
  auto vertex = [&](size_t v, const Vec3& fallback_normal) {
    const Vec3 p3 = transform_point(to_model, {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]});
    Vec3 nn = fallback_normal;
    if (!nrm.empty()) {
      const Vec3 raw{nrm[3 * v], nrm[3 * v + 1], nrm[3 * v + 2]};
      nn = to_vec3(glm::dmat3(carry) * vec(raw));
      const double l = std::sqrt(dot(nn, nn));
      nn = l > 0 ? Vec3{nn[0] / l, nn[1] / l, nn[2] / l} : fallback_normal;
    }
    const float u = uv.empty() ? 0.0f : float(uv[2 * v]), w = uv.empty() ? 0.0f : float(uv[2 * v + 1]);
    out.vertices.insert(out.vertices.end(), {float(p3[0]), float(p3[1]), float(p3[2]), float(nn[0]), float(nn[1]), float(nn[2]), u, w});
  };
  for (size_t t = 0; t < indices.size(); t += 3) {  // unindexed: flat normals need their own vertices
    const Vec3 a = transform_point(to_model, {pos[3 * indices[t]], pos[3 * indices[t] + 1], pos[3 * indices[t] + 2]});
    const Vec3 b = transform_point(to_model, {pos[3 * indices[t + 1]], pos[3 * indices[t + 1] + 1], pos[3 * indices[t + 1] + 2]});
    const Vec3 c = transform_point(to_model, {pos[3 * indices[t + 2]], pos[3 * indices[t + 2] + 1], pos[3 * indices[t + 2] + 2]});
    const Vec3 face = cross(sub(b, a), sub(c, a));
    const double l = std::sqrt(dot(face, face));
    const Vec3 flat = l > 0 ? Vec3{face[0] / l, face[1] / l, face[2] / l} : Vec3{0, 1, 0};
    for (int k = 0; k < 3; ++k) {
      vertex(indices[t + size_t(k)], flat);
      out.indices.push_back(uint32_t(out.indices.size()));
    }
  }
  if (const tinygltf::Material* mat = material_of(m, p)) {
    const auto& f = mat->pbrMetallicRoughness.baseColorFactor;
    if (f.size() >= 3) out.base_color = {f[0], f[1], f[2]};
    out.base_color_texture = texture(m, mat->pbrMetallicRoughness.baseColorTexture.index);
    if (mat->emissiveFactor.size() == 3) out.emissive = {mat->emissiveFactor[0], mat->emissiveFactor[1], mat->emissiveFactor[2]};
    out.emissive_texture = texture(m, mat->emissiveTexture.index);
    read_translucency(m, *mat, length_scale(to_model), out);
  }
  return out;
}

// The images stay encoded (decoded by the passes that sample them); the loader only
// checks that each is an image volgraph can decode.
bool keep_encoded(tinygltf::Image* image, const int index, std::string* error, std::string*, int, int,
                  const unsigned char* bytes, int size, void*) {
  const std::string problem = image_problem(bytes, size_t(size));
  if (!problem.empty()) {
    *error = "image " + std::to_string(index) + (image->name.empty() ? "" : " (" + image->name + ")") + ": " + problem;
    return false;
  }
  image->image.assign(bytes, bytes + size);
  return true;
}

void note_once(std::vector<std::string>& notes, std::string note) {
  if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(std::move(note));
}

// The material extensions the passes draw (the translucency passes, scene.h's Translucency).
bool drawn_extension(const std::string& name) {
  return name == "KHR_materials_transmission" || name == "KHR_materials_ior" || name == "KHR_materials_volume" ||
         name == "KHR_materials_dispersion";
}

// Half float's largest value: the colour targets hold radiance in it (higher is clamped).
constexpr double kMaxHalfRadiance = 65504;

// Refuses a factor with a component outside [lo, hi] (DESIGN.md: bad input is refused
// with one message naming where and what was expected).
void check_range(size_t material, const char* key, const std::vector<double>& factor, double lo, double hi, const char* why) {
  for (double v : factor) {
    if (!(v >= lo && v <= hi)) {
      std::ostringstream s;
      s << "material " << material << ": " << key << " has " << v << "; expected every component in [" << lo << ", " << hi << "] (" << why << ")";
      fail(s.str());
    }
  }
}

// glTF 2.0's material schema: baseColorFactor in [0, 1] (a reflectance); emissiveFactor
// non-negative and, carried as radiance into half-float colour, at most 65504.
void check_material_colours(const tinygltf::Model& m) {
  for (size_t i = 0; i < m.materials.size(); ++i) {
    check_range(i, "pbrMetallicRoughness.baseColorFactor", m.materials[i].pbrMetallicRoughness.baseColorFactor, 0, 1, "glTF 2.0's schema");
    check_range(i, "emissiveFactor", m.materials[i].emissiveFactor, 0, kMaxHalfRadiance, "radiance in half-float colour");
  }
}

// Materials' features the passes do not draw: other extensions, alpha masks in the shadow
// maps, and primitive modes other than triangles.
std::vector<std::string> ignored_features(const tinygltf::Model& m) {
  std::vector<std::string> notes;
  for (const tinygltf::Material& mat : m.materials) {
    for (const auto& [name, value] : mat.extensions) {
      if (!drawn_extension(name)) note_once(notes, name + " (ignored: drawn opaque)");
    }
    if (mat.alphaMode == "MASK") note_once(notes, "alphaMode MASK (cut in the camera's view; the shadow maps are not cut)");
  }
  for (const tinygltf::Mesh& mesh : m.meshes) {
    for (const tinygltf::Primitive& p : mesh.primitives) {
      if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) note_once(notes, "primitive mode " + std::to_string(p.mode) + " (skipped: triangles only)");
    }
  }
  return notes;
}

}  // namespace

size_t GltfModel::triangle_count() const {
  size_t n = 0;
  for (const GltfPrimitive& p : primitives) n += p.indices.size() / 3;
  return n;
}

GltfModel load_gltf(const std::string& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model m;
  std::string error, warning;
  loader.SetImageLoader(keep_encoded, nullptr);
  const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  const bool ok = binary ? loader.LoadBinaryFromFile(&m, &error, &warning, path)
                         : loader.LoadASCIIFromFile(&m, &error, &warning, path);
  if (!ok) fail("malformed glTF: " + (error.empty() ? std::string("tinygltf could not read it") : error));
  for (const std::string& extension : m.extensionsRequired) {
    if (!drawn_extension(extension)) fail("the file requires the glTF extension " + extension + ", which volgraph does not support");
  }
  check_material_colours(m);
  GltfModel model;
  model.ignored = ignored_features(m);
  std::function<void(int, const Mat4&, int)> visit = [&](int node, const Mat4& parent, int depth) {
    if (node < 0 || size_t(node) >= m.nodes.size() || depth > 64) fail("the node hierarchy is broken");
    const tinygltf::Node& n = m.nodes[size_t(node)];
    const Mat4 to_model = parent * node_matrix(n);
    if (n.mesh >= 0) {
      if (size_t(n.mesh) >= m.meshes.size()) fail("a node names a mesh that does not exist");
      for (const tinygltf::Primitive& p : m.meshes[size_t(n.mesh)].primitives) {
        if (p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == -1) model.primitives.push_back(primitive(m, p, to_model));
      }
    }
    for (int child : n.children) visit(child, to_model, depth + 1);
  };
  const int scene = m.defaultScene >= 0 ? m.defaultScene : 0;
  if (m.scenes.empty()) fail("the file has no scene");
  if (size_t(scene) >= m.scenes.size()) fail("the default scene does not exist");
  for (int root : m.scenes[size_t(scene)].nodes) visit(root, Mat4(1), 0);
  if (model.primitives.empty()) fail("the default scene has no triangles");
  for (size_t i = 0; i < m.images.size(); ++i) {
    const std::string name = m.images[i].name.empty() ? m.images[i].uri : m.images[i].name;
    if (m.images[i].image.empty()) {  // tinygltf only warns about an image file it cannot read
      fail("image " + std::to_string(i) + (name.empty() ? "" : " (" + name + ")") + " cannot be read" +
           (warning.empty() ? "" : ": " + warning.substr(0, warning.find('\n'))));
    }
    model.images.push_back({path + " image " + std::to_string(i) + (name.empty() ? "" : " (" + name + ")"), std::move(m.images[i].image)});
  }
  return model;
}

void mark_translucent_gltf_objects(Scene& scene) {
  for (Object& object : scene.objects) {
    if (object.shape != Shape::gltf) continue;
    try {
      const GltfModel model = load_gltf(object.file);
      object.translucent_in_file = std::any_of(model.primitives.begin(), model.primitives.end(),
                                               [](const GltfPrimitive& p) { return p.translucency.translucent(); });
    } catch (const std::exception&) {
      // Left unmarked: the scene pass's checks report the file.
    }
  }
}

}  // namespace volgraph::plumbing
