#include "passes/plumbing/scene_geometry.h"

#include <algorithm>

#include "physics/camera.h"
#include "passes/plumbing/gltf.h"
#include "passes/plumbing/meshes.h"
#include "physics/translucency.h"
#include "shaders/bindings/scene.frag.h"
#include "shaders/bindings/translucency_refract.frag.h"

namespace volgraph::plumbing {

// Set 1, the object's, by scene.frag's names: every program drawing SceneGeometry declares
// it alike (create_render_program's layouts_of checks the programs that share it).
namespace scene_geometry_object_set = shaders::scene_frag;
// Its translucent data textures by translucency_refract.frag's names (translucent_material_textures.glsl).
namespace scene_geometry_translucent_set = shaders::translucency_refract_frag;

using namespace physics;  // the CPU maths these helpers are written in
namespace {

// Binding 0 is the object block (object_uniforms.glsl); 1, 2 and 3 the material's
// textures and sampler (material_textures.glsl), declared by passes that shade; 4 and 5 the
// translucent data textures (translucent_material_textures.glsl), by passes that draw
// translucent surfaces.
bool declares_binding(const rhi::BindGroupLayoutDesc& object_set, uint32_t binding) {
  for (const rhi::LayoutEntry& e : object_set.entries) {
    if (e.binding == binding) return true;
  }
  return false;
}

// A glTF primitive's textures: images of the model, decoded when first bound.
MaterialTextures gltf_textures(const GltfModel& model, const GltfPrimitive& p) {
  MaterialTextures t;
  auto image = [&model](const GltfTexture& texture) -> std::function<Rgba8Image()> {
    if (!texture) return nullptr;
    const GltfImage* source = &model.images[size_t(texture.image)];
    return [source] { return source->decode(); };
  };
  t.base_color = image(p.base_color_texture);
  t.emissive = image(p.emissive_texture);
  if (p.base_color_texture) t.base_color_key = model.images[size_t(p.base_color_texture.image)].name;
  if (p.emissive_texture) t.emissive_key = model.images[size_t(p.emissive_texture.image)].name;
  t.transmission = image(p.transmission_texture);
  t.thickness = image(p.thickness_texture);
  if (p.transmission_texture) t.transmission_key = model.images[size_t(p.transmission_texture.image)].name;
  if (p.thickness_texture) t.thickness_key = model.images[size_t(p.thickness_texture.image)].name;
  t.wrap = p.base_color_texture ? p.base_color_texture.wrap : p.emissive_texture.wrap;
  return t;
}

MaterialTextures config_textures(const Material* m) {
  MaterialTextures t;
  if (!m || m->albedo_texture.empty()) return t;
  const std::string path = m->albedo_texture;
  t.base_color = [path] { return read_image_file(path); };
  t.base_color_key = path;
  return t;
}

// The block's translucency (shaders/include/object_uniforms.glsl's codes), lengths carried
// from the object's space into the world's by the model matrix's `scale`.
void pack_translucency(const Translucency& t, double scale, GpuObjectBlock& block) {
  block.translucency[0] = float(t.alpha);
  block.translucency[1] = float(t.transmission);
  block.translucency[2] = float(t.ior);
  block.translucency[3] = float(t.thickness * scale);
  block.emissive[3] = float(t.roughness);
  for (size_t i = 0; i < 3; ++i) block.attenuation[i] = float(sigma_t_from_color(t.attenuation_color[i], t.attenuation_distance * scale));
  block.attenuation[3] = float(int(t.volume));
  block.alpha_test[0] = float(int(t.alpha_mode));
  block.alpha_test[1] = float(t.alpha_cutoff);
  // KHR_materials_dispersion: the red and blue channels' IORs (the translucency shaders' channel_iors).
  const std::array<double, 3> iors = physics::dispersed_iors(t.ior, t.dispersion);
  block.alpha_test[2] = float(iors[0]);
  block.alpha_test[3] = float(iors[2]);
}

// Whether every vertex lies on or behind every triangle's plane (the normal by the
// counter-clockwise winding): a convex mesh or a flat one, covering a pixel at most once
// per face set. Meshes of more than 1e8 vertex-triangle pairs count as not convex.
bool convex_mesh(const std::vector<float>& vertices, const std::vector<uint32_t>& indices) {
  const size_t vertex_count = vertices.size() / kMeshVertexFloats, triangles = indices.size() / 3;
  if (double(vertex_count) * double(triangles) > 1e8) return false;
  const auto point = [&](size_t v) {
    const float* p = &vertices[v * kMeshVertexFloats];
    return Vec3{p[0], p[1], p[2]};
  };
  double extent = 0;
  for (size_t v = 0; v < vertex_count; ++v) extent = std::max(extent, physics::largest(physics::times(point(v), point(v))));
  const double tolerance = 1e-5 * std::sqrt(extent);
  for (size_t t = 0; t < triangles; ++t) {
    const Vec3 a = point(indices[3 * t]), b = point(indices[3 * t + 1]), c = point(indices[3 * t + 2]);
    const Vec3 n = physics::cross(physics::sub(b, a), physics::sub(c, a));
    const double area = physics::length_of(n);
    if (area == 0) continue;
    for (size_t v = 0; v < vertex_count; ++v) {
      if (physics::dot(physics::sub(point(v), a), n) > tolerance * area) return false;
    }
  }
  return true;
}

}  // namespace

rhi::VertexBufferLayout SceneGeometry::vertex_layout() {
  using rhi::VertexFormat;
  return {kMeshVertexFloats * 4, {{0, VertexFormat::float32x3, 0}, {1, VertexFormat::float32x3, 12}, {2, VertexFormat::float32x2, 24}}};
}

rhi::VertexBufferLayout SceneGeometry::position_uv_layout() {
  return {kMeshVertexFloats * 4, {{0, rhi::VertexFormat::float32x3, 0}, {2, rhi::VertexFormat::float32x2, 24}}};
}

rhi::VertexBufferLayout SceneGeometry::position_layout() {
  return {kMeshVertexFloats * 4, {{0, rhi::VertexFormat::float32x3, 0}}};
}

std::vector<rhi::BoundResource> SceneGeometry::texture_entries(const MaterialTextures& t) {
  namespace set = scene_geometry_object_set;
  return {bind(set::base_color_texture, t.base_color ? textures_->srgb(t.base_color_key, t.base_color) : textures_->white()),
          bind(set::emissive_texture, t.emissive ? textures_->srgb(t.emissive_key, t.emissive) : textures_->white()),
          bind(set::material_sampler, textures_->sampler(t.wrap))};
}

std::vector<rhi::BoundResource> SceneGeometry::translucent_texture_entries(const MaterialTextures& t) {
  namespace set = scene_geometry_translucent_set;
  return {bind(set::transmission_texture, t.transmission ? textures_->linear(t.transmission_key, t.transmission) : textures_->white()),
          bind(set::thickness_texture, t.thickness ? textures_->linear(t.thickness_key, t.thickness) : textures_->white())};
}

void SceneGeometry::add(rhi::Device& device, const ObjectData& object) {
  using namespace rhi;
  Vec3 object_min{1e30, 1e30, 1e30}, object_max{-1e30, -1e30, -1e30};
  for (size_t v = 0; v < object.vertices.size(); v += kMeshVertexFloats) {
    const Vec3 p = transform_point(object.model, {object.vertices[v], object.vertices[v + 1], object.vertices[v + 2]});
    for (size_t k = 0; k < 3; ++k) {
      object_min[k] = std::min(object_min[k], p[k]);
      object_max[k] = std::max(object_max[k], p[k]);
    }
  }
  for (size_t k = 0; k < 3; ++k) {
    min_[k] = std::min(min_[k], object_min[k]);
    max_[k] = std::max(max_[k], object_max[k]);
  }
  GpuObject g;
  g.index_count = uint32_t(object.indices.size());
  g.translucent = object.translucency.translucent();
  g.casts_shadows = object.casts_shadows;
  g.masked = object.translucency.alpha_mode == AlphaMode::mask;
  g.volume = object.translucency.volume;
  g.center = physics::scaled(physics::add(object_min, object_max), 0.5);
  g.convex = g.translucent && convex_mesh(object.vertices, object.indices);
  g.vertices = device.create_buffer({"object vertices", object.vertices.size() * 4, buffer_usage::vertex});
  device.write_buffer(g.vertices, 0, std::as_bytes(std::span(object.vertices)));
  g.indices = device.create_buffer({"object indices", object.indices.size() * 4, buffer_usage::index});
  device.write_buffer(g.indices, 0, std::as_bytes(std::span(object.indices)));
  GpuObjectBlock block{};
  to_floats(object.model, block.model);
  to_floats(normal_matrix(object.model), block.normal_matrix);
  for (size_t i = 0; i < 3; ++i) {
    block.albedo[i] = float(object.albedo[i]);
    block.emissive[i] = float(object.emissive[i]);
  }
  pack_translucency(object.translucency, length_scale(object.model), block);
  g.uniforms = device.create_buffer({"object", sizeof(GpuObjectBlock), buffer_usage::uniform});
  device.write_buffer(g.uniforms, 0, std::as_bytes(std::span(&block, 1)));
  std::vector<BoundResource> resources = {bind(scene_geometry_object_set::object, g.uniforms)};
  if (textured_) {
    for (const BoundResource& t : texture_entries(object.textures)) resources.push_back(t);
  }
  if (translucent_textured_) {
    for (const BoundResource& t : translucent_texture_entries(object.textures)) resources.push_back(t);
  }
  g.group = device.create_bind_group({"object", layout_, entries_of(resources)});
  objects_.push_back(g);
}

SceneGeometry::SceneGeometry(rhi::Device& device, const Scene& scene, const RenderProgram& program)
    : textured_(declares_binding(program.layout_descs.at(1), 1)),
      translucent_textured_(declares_binding(program.layout_descs.at(1), 4)),
      textures_(std::make_unique<TextureCache>(device)),
      layout_(program.layouts.at(1)) {
  check_wrapped_uniform_mirror<GpuObjectBlock>(program, scene_geometry_object_set::object, "gpu::ObjectUniforms");
  for (const Object& object : scene.objects) {
    const Mat4 model = model_matrix(object.transform);
    if (object.shape == Shape::gltf) {
      const GltfModel gltf = load_gltf(object.file);
      for (const GltfPrimitive& p : gltf.primitives) {
        // The images must outlive the loads the cache makes while binding (inside add).
        const MaterialTextures textures = gltf_textures(gltf, p);
        add(device, {p.vertices, p.indices, model, p.base_color, p.emissive, p.translucency, textures, object.cast_shadows});
      }
      continue;
    }
    const Mesh mesh = primitive_mesh(object.shape, object.size);
    const Material* m = scene.find_material(object.material);
    const MaterialTextures textures = config_textures(m);
    const Material fallback;
    const Material& material = m ? *m : fallback;
    add(device, {mesh.vertices, mesh.indices, model, material.albedo, material.emissive, material.translucency, textures, object.cast_shadows});
  }
}

void SceneGeometry::draw(rhi::CommandEncoder& encoder, uint32_t set, Surfaces which) const {
  for (const GpuObject& o : objects_) {
    if (o.is(which)) draw(encoder, set, o);
  }
}

void SceneGeometry::draw(rhi::CommandEncoder& encoder, uint32_t set, const GpuObject& o) {
  encoder.set_bind_group(set, o.group);
  encoder.set_vertex_buffer(0, o.vertices);
  encoder.set_index_buffer(o.indices, rhi::IndexFormat::uint32);
  encoder.draw_indexed(o.index_count);
}

bool SceneGeometry::any(Surfaces which) const {
  return std::any_of(objects_.begin(), objects_.end(), [&](const GpuObject& o) { return o.is(which); });
}

}  // namespace volgraph::plumbing
