// Opaque scene: Lambertian surfaces lit by the scene's lights (DESIGN.md units:
// ρ/π · E · cos θ · V), emissive surfaces and the background radiance.
#include <cstring>

#include "graph/execute/pass_execution.h"
#include "graph/rhi/device_error.h"
#include "graph/scene/scene.h"
#include "passes/passes.h"
#include "passes/shading/camera.h"
#include "passes/shading/gltf.h"
#include "passes/shading/light_list.h"
#include "passes/shading/programs.h"
#include "passes/shading/scene_geometry.h"
#include "passes/shading/textures.h"

namespace volgraph {
namespace {

// std140 block Frame of shaders/include/scene_uniforms.glsl.
struct FrameBlock {
  float view_projection[16];
  float ambient_irradiance[4];
  shading::GpuLightList light_list;
};

// glTF files must load and textures decode: a malformed one is bad input, reported at
// the object's "file" or the material's "albedo_texture".
std::vector<ParamProblem> check_models(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  std::vector<ParamProblem> problems;
  for (const Material& m : scene.materials) {
    if (m.albedo_texture.empty()) continue;
    const std::string problem = shading::image_file_problem(m.albedo_texture);
    if (problem.empty()) continue;
    Where where = m.where;
    where.pointer += "/albedo_texture";
    problems.push_back({"", m.albedo_texture + ": " + problem, where});
  }
  for (const Object& o : scene.objects) {
    if (o.shape != Shape::gltf) continue;
    try {
      shading::load_gltf(o.file);
    } catch (const std::exception& e) {
      Where where = o.where;
      where.pointer += "/file";
      problems.push_back({"", o.file + ": " + e.what(), where});
    }
  }
  return problems;
}

// Rasterises the scene's objects, lit (shaders/scene.vert, scene.frag).
class SceneExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    write_frame(c);
    const Vec3& bg = c.scene->background;
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name;
    pass.colors = {{c.view("color"), rhi::LoadOp::clear, {float(bg[0]), float(bg[1]), float(bg[2]), 1.0f}}};
    pass.depth = {c.view("depth"), rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(program_.pipeline);
    c.encoder.set_bind_group(0, frame_group_);
    if (shadow_group_) c.encoder.set_bind_group(2, shadow_group_);
    geometry_->draw(c.encoder, 1);
    c.encoder.end_render_pass();
  }

 private:
  void write_frame(PassContext& c) {
    const Scene& scene = *c.scene;
    const Extent size = c.desc("color").extent;
    FrameBlock f{};
    to_floats(shading::view_projection(scene.camera, double(size.width) / size.height), f.view_projection);
    const auto ambient = std::get<std::array<double, 3>>(c.param("ambient"));
    for (size_t i = 0; i < 3; ++i) f.ambient_irradiance[i] = float(ambient[i]);
    f.light_list = shading::pack_lights(scene.lights);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&f, 1)));
  }

  void prepare(PassContext& c) {
    using namespace rhi;
    const Scene& scene = *c.scene;
    // With a shadow map wired (and shadows on), its light is shadowed (set 2).
    const bool shadowed = c.bound("shadow_map") && c.bound("light_view") && std::get<bool>(c.param("shadows"));
    const bool media_shadowed = shadowed && c.bound("media_shadow");
    RenderPipelineDesc pd;
    pd.label = "scene";
    pd.vertex_buffers = {shading::SceneGeometry::vertex_layout()};
    pd.colors = {{c.desc("color").format, BlendMode::replace}};
    pd.depth = {Format::d32_float, true, CompareFunction::less};
    pd.cull = CullMode::none;  // planes are seen from both sides
    program_ = shading::create_render_program(c.device, pd, "scene.vert",
                                              media_shadowed ? "scene_media_shadowed.frag"
                                              : shadowed     ? "scene_shadowed.frag"
                                                             : "scene.frag");

    frame_ = c.device.create_buffer({"scene frame", sizeof(FrameBlock), buffer_usage::uniform | buffer_usage::copy_dst});
    frame_group_ = c.device.create_bind_group({"scene frame", program_.layouts[0], {BindGroupEntry::of(0, frame_)}});
    geometry_ = std::make_unique<shading::SceneGeometry>(c.device, scene, program_.layout_descs[1], program_.layouts[1]);
    if (!shadowed) return;
    std::vector<BindGroupEntry> shadow = {BindGroupEntry::of(0, c.view("shadow_map")),
                                          BindGroupEntry::of(1, c.device.create_sampler({"shadow nearest"})),
                                          BindGroupEntry::of(2, c.buffer("light_view"))};
    if (media_shadowed) {
      shadow.push_back(BindGroupEntry::of(3, c.view("media_shadow")));
      shadow.push_back(BindGroupEntry::of(4, c.device.create_sampler({"media shadow", Filter::linear})));
    }
    shadow_group_ = c.device.create_bind_group({"scene shadow", program_.layouts[2], shadow});
  }

  shading::RenderProgram program_;
  rhi::BufferId frame_;
  rhi::BindGroupId frame_group_;
  rhi::BindGroupId shadow_group_;
  std::unique_ptr<shading::SceneGeometry> geometry_;
};

}  // namespace

PassDecl scene_pass() {
  PassDecl d;
  d.name = "scene";
  d.kind = PassKind::graphics;
  d.doc = "Opaque surfaces, lit and shadowed, over the background; linear radiance and depth.";
  d.variants = {{"lambert", "Lambertian reflection of every light, shadowed by the shadow map (and the media's opacity shadow map) when wired"}};
  d.params = {
      param_vec3("ambient", {0, 0, 0}, 0, 1e6, "W/m²", "uniform irradiance added to every surface (unshadowed)"),
      param_bool("shadows", true, "sample the shadow map when one is wired"),
  };
  SlotDecl color = slot_out("color", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float,
                            SizeSpec::of_output(), "linear radiance");
  color.format_overridable = true;
  color.size_overridable = true;
  d.slots = {
      slot_optional_in("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map"),
      slot_optional_in("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view"),
      slot_optional_in("media_shadow", ResourceKind::texture3d, Usage::sampled,
                       "opacity_shadow_map's optical depth over the same light view: the media dim that light"),
      color,
      slot_out("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float, SizeSpec::of_output(),
               "scene depth, for later passes (fog, translucency)"),
  };
  d.slots[0].format = Format::d32_float;
  d.check_scene = check_models;
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new SceneExecution()); };
  return d;
}

}  // namespace volgraph
