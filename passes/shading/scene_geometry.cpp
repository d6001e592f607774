#include "passes/shading/scene_geometry.h"

#include <algorithm>

#include "passes/shading/camera.h"
#include "passes/shading/gltf.h"
#include "passes/shading/meshes.h"

namespace volgraph::shading {
namespace {

struct ObjectBlock {  // std140, shaders/include/scene_uniforms.glsl
  float model[16];
  float normal_matrix[16];
  float albedo[4];
  float emissive[4];
};


}  // namespace

void SceneGeometry::add(rhi::Device& device, const std::vector<float>& vertices, const std::vector<uint32_t>& indices,
                        const Mat4& model, const Vec3& albedo, const Vec3& emissive) {
  using namespace rhi;
  for (size_t v = 0; v < vertices.size(); v += 6) {
    const Vec3 p = transform_point(model, {vertices[v], vertices[v + 1], vertices[v + 2]});
    for (size_t k = 0; k < 3; ++k) {
      min_[k] = std::min(min_[k], p[k]);
      max_[k] = std::max(max_[k], p[k]);
    }
  }
  GpuObject g;
  g.index_count = uint32_t(indices.size());
  g.vertices = device.create_buffer({"object vertices", vertices.size() * 4, buffer_usage::vertex});
  device.write_buffer(g.vertices, 0, std::as_bytes(std::span(vertices)));
  g.indices = device.create_buffer({"object indices", indices.size() * 4, buffer_usage::index});
  device.write_buffer(g.indices, 0, std::as_bytes(std::span(indices)));
  ObjectBlock block{};
  to_floats(model, block.model);
  to_floats(normal_matrix(model), block.normal_matrix);
  for (size_t i = 0; i < 3; ++i) {
    block.albedo[i] = float(albedo[i]);
    block.emissive[i] = float(emissive[i]);
  }
  g.uniforms = device.create_buffer({"object", sizeof(ObjectBlock), buffer_usage::uniform});
  device.write_buffer(g.uniforms, 0, std::as_bytes(std::span(&block, 1)));
  BindGroupEntry e;
  e.buffer = g.uniforms;
  g.group = device.create_bind_group({"object", layout_, {e}});
  objects_.push_back(g);
}

SceneGeometry::SceneGeometry(rhi::Device& device, const Scene& scene) {
  using namespace rhi;
  layout_ = device.create_bind_group_layout(
      {"scene object", {{0, shader_stage::vertex | shader_stage::fragment, BindingType::uniform_buffer}}});
  for (const Object& object : scene.objects) {
    const Mat4 model = model_matrix(object.transform);
    if (object.shape == Shape::gltf) {
      // Factors only: base colour and emission textures are not read yet (an emission
      // factor whose texture would modulate it is left out rather than applied flat).
      for (const GltfPrimitive& p : load_gltf(object.file).primitives) {
        add(device, p.vertices, p.indices, model, p.base_color, p.emissive_texture ? Vec3{0, 0, 0} : p.emissive);
      }
      continue;
    }
    const Mesh mesh = primitive_mesh(object.shape, object.size);
    const Material* m = scene.find_material(object.material);
    add(device, mesh.vertices, mesh.indices, model, m ? m->albedo : Vec3{0.8, 0.8, 0.8}, m ? m->emissive : Vec3{0, 0, 0});
  }
}

void SceneGeometry::draw(rhi::CommandEncoder& encoder, uint32_t set) const {
  for (const GpuObject& o : objects_) {
    encoder.set_bind_group(set, o.group);
    encoder.set_vertex_buffer(0, o.vertices);
    encoder.set_index_buffer(o.indices, rhi::IndexFormat::uint32);
    encoder.draw_indexed(o.index_count);
  }
}

}  // namespace volgraph::shading
