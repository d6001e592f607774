#include "reference/scene_triangles.h"

#include <algorithm>
#include <map>
#include <string>

#include "physics/camera.h"
#include "passes/plumbing/gltf.h"
#include "passes/plumbing/meshes.h"
#include "physics/translucency.h"

namespace volgraph::reference {
namespace {

using plumbing::kMeshVertexFloats;
using physics::Mat4;

// Decodes each image once, however many objects use it.
class ImageTable {
 public:
  explicit ImageTable(std::vector<LinearImage>& images) : images_(images) {}
  // `data`: stored linear (no sRGB decode), kept apart from a colour use of the same image.
  int index(const std::string& key, const std::function<plumbing::Rgba8Image()>& load, bool data = false) {
    const std::string entry = data ? "data " + key : key;
    const auto found = indices_.find(entry);
    if (found != indices_.end()) return found->second;
    images_.push_back(data ? data_image(load()) : linear_image(load()));
    return indices_[entry] = int(images_.size() - 1);
  }

 private:
  std::vector<LinearImage>& images_;
  std::map<std::string, int> indices_;
};

// The vertex shader's work on one vertex: world position, world normal (not normalised).
struct WorldVertex {
  Vec3 position, normal;
  std::array<double, 2> uv;
};

WorldVertex world_vertex(const std::vector<float>& vertices, uint32_t index, const Mat4& model, const Mat4& normals) {
  const float* v = vertices.data() + size_t(index) * kMeshVertexFloats;
  WorldVertex w;
  w.position = physics::transform_point(model, {v[0], v[1], v[2]});
  w.normal = physics::to_vec3(glm::dmat3(normals) * glm::dvec3(v[3], v[4], v[5]));
  w.uv = {v[6], v[7]};
  return w;
}

void add_mesh(SceneTriangles& out, const std::vector<float>& vertices, const std::vector<uint32_t>& indices,
              const Object& object, uint32_t object_index, uint32_t material) {
  const Mat4 model = physics::model_matrix(object.transform), normals = physics::normal_matrix(model);
  for (size_t i = 0; i + 2 < indices.size(); i += 3) {
    const WorldVertex a = world_vertex(vertices, indices[i], model, normals);
    const WorldVertex b = world_vertex(vertices, indices[i + 1], model, normals);
    const WorldVertex c = world_vertex(vertices, indices[i + 2], model, normals);
    out.triangles.push_back({a.position, b.position, c.position});
    out.attributes.push_back({{a.normal, b.normal, c.normal}, {a.uv, b.uv, c.uv}, material, object_index});
    out.casts_shadows.push_back(object.cast_shadows);
  }
}

// The material's translucency in world metres, by the object's length scale (as
// passes/plumbing/scene_geometry.cpp packs it for the GPU).
void set_translucency(SurfaceMaterial& m, const Translucency& t, double scale) {
  m.translucency = t;
  m.translucency.thickness = t.thickness * scale;
  m.translucency.attenuation_distance = t.attenuation_distance * scale;
  for (size_t c = 0; c < 3; ++c) m.sigma_t[c] = physics::sigma_t_from_color(t.attenuation_color[c], m.translucency.attenuation_distance);
}

uint32_t add_gltf_material(SceneTriangles& out, ImageTable& table, const plumbing::GltfModel& model,
                           const plumbing::GltfPrimitive& p, double scale) {
  SurfaceMaterial m;
  set_translucency(m, p.translucency, scale);
  m.albedo = p.base_color;
  m.emissive = p.emissive;
  auto image = [&](const plumbing::GltfTexture& texture, bool data) {
    if (!texture) return -1;
    const plumbing::GltfImage& source = model.images[size_t(texture.image)];
    return table.index(source.name + "#" + std::to_string(texture.image), [&source] { return source.decode(); }, data);
  };
  m.base_color_image = image(p.base_color_texture, false);
  m.emissive_image = image(p.emissive_texture, false);
  m.transmission_image = image(p.transmission_texture, true);
  m.thickness_image = image(p.thickness_texture, true);
  m.wrap = p.base_color_texture ? p.base_color_texture.wrap : p.emissive_texture.wrap;  // one sampler, as the GPU
  out.materials.push_back(m);
  return uint32_t(out.materials.size() - 1);
}

uint32_t add_config_material(SceneTriangles& out, ImageTable& table, const Material* material, double scale) {
  SurfaceMaterial m;
  set_translucency(m, Translucency{}, scale);
  if (material) {
    set_translucency(m, material->translucency, scale);
    m.albedo = material->albedo;
    m.emissive = material->emissive;
    const std::string path = material->albedo_texture;
    if (!path.empty()) m.base_color_image = table.index(path, [&path] { return plumbing::read_image_file(path); });
  }
  out.materials.push_back(m);
  return uint32_t(out.materials.size() - 1);
}

Vec3 textured(const SceneTriangles& scene, const Vec3& factor, int image, plumbing::SamplerWrap wrap, double u, double v) {
  if (image < 0) return factor;
  const Vec3 t = sample_bilinear(scene.images[size_t(image)], wrap, u, v);
  return {factor[0] * t[0], factor[1] * t[1], factor[2] * t[2]};
}

}  // namespace

SceneTriangles scene_triangles(const Scene& scene) {
  SceneTriangles out;
  ImageTable table(out.images);
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    const Object& object = scene.objects[o];
    const double scale = physics::length_scale(physics::model_matrix(object.transform));
    if (object.shape == Shape::gltf) {
      const plumbing::GltfModel model = plumbing::load_gltf(object.file);
      for (const plumbing::GltfPrimitive& p : model.primitives) {
        add_mesh(out, p.vertices, p.indices, object, o, add_gltf_material(out, table, model, p, scale));
      }
      continue;
    }
    const plumbing::Mesh mesh = plumbing::primitive_mesh(object.shape, object.size);
    add_mesh(out, mesh.vertices, mesh.indices, object, o, add_config_material(out, table, scene.find_material(object.material), scale));
  }
  return out;
}

bool is_translucent(const SurfaceMaterial& m) { return m.translucency.translucent(); }

double coverage_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v) {
  const double texture = m.base_color_image < 0 ? 1.0 : sample_alpha_bilinear(scene.images[size_t(m.base_color_image)], m.wrap, u, v);
  return std::clamp(m.translucency.alpha * texture, 0.0, 1.0);
}

double layer_coverage(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v) {
  return m.translucency.alpha_mode == AlphaMode::blend ? coverage_at(scene, m, u, v) : 1.0;
}

bool is_hole(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v) {
  return m.translucency.alpha_mode == AlphaMode::mask && coverage_at(scene, m, u, v) < m.translucency.alpha_cutoff;
}

Vec3 albedo_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v) {
  return textured(scene, m.albedo, m.base_color_image, m.wrap, u, v);
}

Vec3 emission_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v) {
  return textured(scene, m.emissive, m.emissive_image, m.wrap, u, v);
}

double transmission_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v) {
  return textured(scene, {1, 1, 1}, m.transmission_image, m.wrap, u, v)[0] * m.translucency.transmission;
}

double thickness_at(const SceneTriangles& scene, const SurfaceMaterial& m, double u, double v) {
  return textured(scene, {1, 1, 1}, m.thickness_image, m.wrap, u, v)[1] * m.translucency.thickness;
}

}  // namespace volgraph::reference
