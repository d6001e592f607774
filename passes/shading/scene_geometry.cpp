#include "passes/shading/scene_geometry.h"

#include <algorithm>

#include "graph/rhi/device_error.h"
#include "passes/shading/camera.h"
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

SceneGeometry::SceneGeometry(rhi::Device& device, const Scene& scene) {
  using namespace rhi;
  layout_ = device.create_bind_group_layout(
      {"scene object", {{0, shader_stage::vertex | shader_stage::fragment, BindingType::uniform_buffer}}});
  for (size_t index = 0; index < scene.objects.size(); ++index) {
    const Object& object = scene.objects[index];
    if (object.shape == Shape::gltf) {
      throw DeviceError(DeviceError::Kind::unsupported,
                        "glTF objects (scene object " + std::to_string(index) + ") have no GPU implementation yet");
    }
    const Mesh mesh = primitive_mesh(object.shape, object.size);
    const Mat4 model = model_matrix(object.transform);
    for (size_t v = 0; v < mesh.vertices.size(); v += 6) {
      const Vec3 p = transform_point(model, {mesh.vertices[v], mesh.vertices[v + 1], mesh.vertices[v + 2]});
      for (size_t k = 0; k < 3; ++k) {
        min_[k] = std::min(min_[k], p[k]);
        max_[k] = std::max(max_[k], p[k]);
      }
    }
    GpuObject g;
    g.index_count = uint32_t(mesh.indices.size());
    g.vertices = device.create_buffer({"object vertices", mesh.vertices.size() * 4, buffer_usage::vertex});
    device.write_buffer(g.vertices, 0, std::as_bytes(std::span(mesh.vertices)));
    g.indices = device.create_buffer({"object indices", mesh.indices.size() * 4, buffer_usage::index});
    device.write_buffer(g.indices, 0, std::as_bytes(std::span(mesh.indices)));
    ObjectBlock block{};
    to_floats(model, block.model);
    to_floats(normal_matrix(model), block.normal_matrix);
    const Material* m = scene.find_material(object.material);
    for (size_t i = 0; i < 3; ++i) {
      block.albedo[i] = m ? float(m->albedo[i]) : 0.8f;
      block.emissive[i] = m ? float(m->emissive[i]) : 0.0f;
    }
    g.uniforms = device.create_buffer({"object", sizeof(ObjectBlock), buffer_usage::uniform});
    device.write_buffer(g.uniforms, 0, std::as_bytes(std::span(&block, 1)));
    BindGroupEntry e;
    e.buffer = g.uniforms;
    g.group = device.create_bind_group({"object", layout_, {e}});
    objects_.push_back(g);
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
