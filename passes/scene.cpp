// Opaque scene: Lambertian surfaces lit by the scene's lights (DESIGN.md units:
// ρ/π · E · cos θ · V, V the shadow map's visibility times the media's transmittance
// toward the light — the global and height fog's in closed form always, the local volumes'
// through an opacity shadow map when one is wired, as the CPU reference dims surfaces, and
// the translucent casters' coloured transmittance through a translucent_shadow_map when one is,
// and the sun through the cloud layer, exp(−τ) from a cloud_shadow_map, when one is),
// emissive surfaces and the background radiance.
#include <cstring>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/rhi/device_error.h"
#include "graph/scene/scene.h"
#include "passes/register_pass.h"
#include "physics/camera.h"
#include "passes/plumbing/gltf.h"
#include "passes/plumbing/light_list.h"
#include "passes/plumbing/scene_lighting.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/scene_geometry.h"
#include "passes/plumbing/shadow_view.h"
#include "passes/plumbing/textures.h"
#include "passes/uniform_mirrors.h"
#include "shaders/bindings/scene.vert.h"
#include "shaders/bindings/scene_media_translucent_shadowed.frag.h"
#include "shaders/bindings/scene_shadowed_cloud_shadowed.frag.h"
#include "shaders/include/cloud_shadow_view.h"

namespace volgraph {
namespace {

namespace scene_vert_shader = shaders::scene_vert;
// The shadowed fragment shaders share set 2; the media- and translucent-shadowed one declares all of it.
namespace scene_shadow_shader = shaders::scene_media_translucent_shadowed_frag;
// The cloud-shadowed ones add bindings 7–9 of set 2.
namespace scene_cloud_shadow_shader = shaders::scene_shadowed_cloud_shadowed_frag;

// glTF files must load and textures decode: a malformed one is bad input, reported at
// the object's "file" or the material's "albedo_texture"; and the scene must fit the
// draws the GPU passes can make (plumbing::kMaxSceneDraws), reported at the first
// object past them.
std::vector<ParamProblem> check_models(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  std::vector<ParamProblem> problems;
  for (const Material& m : scene.materials) {
    if (m.albedo_texture.empty()) continue;
    const std::string problem = plumbing::image_file_problem(m.albedo_texture);
    if (problem.empty()) continue;
    Where where = m.where;
    where.pointer += "/albedo_texture";
    problems.push_back({"", m.albedo_texture + ": " + problem, where});
  }
  size_t draws = 0;
  for (const Object& o : scene.objects) {
    const size_t before = draws;
    if (o.shape != Shape::gltf) {
      ++draws;
    } else {
      Where where = o.where;
      where.pointer += "/file";
      try {
        const plumbing::GltfModel model = plumbing::load_gltf(o.file);
        draws += model.primitives.size();
        for (const std::string& ignored : model.ignored) problems.push_back({"", o.file + ": " + ignored, where, true});
      } catch (const std::exception& e) {
        problems.push_back({"", o.file + ": " + e.what(), where});
      }
    }
    if (before <= plumbing::kMaxSceneDraws && draws > plumbing::kMaxSceneDraws) {
      problems.push_back({"", "the scene's objects make more than " + std::to_string(plumbing::kMaxSceneDraws) +
                                  " draws from here on (a glTF object one per primitive); at most " +
                                  std::to_string(plumbing::kMaxSceneDraws) + " are supported",
                          o.where});
    }
  }
  return problems;
}

struct SceneTable : PassTable {
  SceneTable()
      : PassTable("scene", PassKind::graphics, "Opaque surfaces, lit and shadowed, over the background; linear radiance and depth.") {
    decl.check_scene = check_models;
  }
  // Variants.
  VariantHandle lambert = variant(
      "lambert", "Lambertian reflection of every light, shadowed by the shadow map (and the media's opacity shadow map) when wired");
  // Parameters.
  ParamHandle<std::array<double, 3>> ambient =
      vec3("ambient", {0, 0, 0}, 0, 1e6, "W/m²", "uniform irradiance added to every surface (unshadowed), beside the sky's π·L_sky under an atmosphere");
  ParamHandle<bool> shadows = flag("shadows", true, "sample the shadow map when one is wired");
  // Slots.
  SlotHandle shadow_map = optional_input("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map",
                                         {.format = Format::d32_float});
  SlotHandle light_view = optional_input("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view");
  SlotHandle media_shadow = optional_input("media_shadow", ResourceKind::texture3d, Usage::sampled,
                                           "opacity_shadow_map's optical depth over the same light view: the media dim that light");
  SlotHandle translucent_shadow = optional_input("translucent_shadow", ResourceKind::texture2d, Usage::sampled,
                                                 "translucent_shadow_map's transmittance over the same light view: translucent casters tint that light",
                                                 {.format = Format::rgba16_float});
  SlotHandle translucent_shadow_depth = optional_input("translucent_shadow_depth", ResourceKind::texture2d, Usage::sampled,
                                                       "translucent_shadow_map's depth: only receivers behind its casters are tinted",
                                                       {.format = Format::d32_float});
  SlotHandle cloud_shadow = optional_input("cloud_shadow", ResourceKind::texture2d, Usage::sampled,
                                           "cloud_shadow_map's optical depth: the cloud layer dims the sun by exp(−τ)",
                                           {.format = Format::rgba16_float});
  SlotHandle cloud_shadow_view = optional_input("cloud_shadow_view", ResourceKind::buffer, Usage::uniform_read,
                                                "cloud_shadow_map's view (where its square lies, toward which sun)");
  SlotHandle color = output("color", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float, SizeSpec::of_output(),
                            "linear radiance", {.format_overridable = true, .size_overridable = true});
  SlotHandle depth = output("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float, SizeSpec::of_output(),
                            "scene depth, for later passes (fog, translucency)");
  SlotHandle frame = output("frame", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(kSceneFrameBytes),
                            "the surfaces' lighting block (shaders/include/scene_uniforms.glsl's Frame), for the passes that "
                            "shade surfaces after it (translucency): the same lights, ambient and fog");
};

// Rasterises the scene's objects, lit (shaders/scene.vert, scene.frag).
class SceneExecution final : public PassExecution {
 public:
  explicit SceneExecution(const SceneTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    using namespace rhi;
    // With a shadow map wired (and shadows on), its light is shadowed (set 2).
    shadowed_ = s.bound(t_.shadow_map) && s.bound(t_.light_view) && s.param(t_.shadows);
    media_shadowed_ = shadowed_ && s.bound(t_.media_shadow);
    translucent_shadowed_ = shadowed_ && s.bound(t_.translucent_shadow) && s.bound(t_.translucent_shadow_depth);
    cloud_shadowed_ = s.bound(t_.cloud_shadow) && s.bound(t_.cloud_shadow_view);
    RenderPipelineDesc pd;
    pd.label = "scene";
    pd.vertex_buffers = {plumbing::SceneGeometry::vertex_layout()};
    pd.colors = {{s.desc(t_.color).format, BlendMode::replace}};
    pd.depth = {Format::d32_float, true, CompareFunction::less};
    pd.cull = CullMode::none;  // planes are seen from both sides
    program_ = plumbing::create_render_program(s.device, pd, "scene.vert", fragment_shader());
    // The blocks it fills (the frame every frame; the objects' in SceneGeometry) and the
    // shadow map's view it reads match the shaders'.
    plumbing::check_wrapped_uniform_mirror<gpu::SceneFrame>(program_, scene_vert_shader::frame, "scene frame");
    if (shadowed_) plumbing::check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(program_, scene_shadow_shader::shadow, s.name() + " light_view");
    if (cloud_shadowed_)
      plumbing::check_wrapped_uniform_mirror<gpu::CloudShadowView>(program_, scene_cloud_shadow_shader::cloud_shadow_view,
                                                                   s.name() + " cloud_shadow_view");
    frame_ = s.device.create_buffer({"scene frame", sizeof(gpu::SceneFrame), buffer_usage::uniform | buffer_usage::copy_dst});
    geometry_ = std::make_unique<plumbing::SceneGeometry>(s.device, *s.scene, program_);
  }

  void record(PassContext& c) override {
    const gpu::SceneFrame f = frame_of(c);
    const auto bytes = std::as_bytes(std::span(&f, 1));
    c.device.write_buffer(frame_, 0, bytes);                // for this pass's shaders
    c.encoder.update_buffer(c.buffer(t_.frame), 0, bytes);  // for the passes after it
    const Vec3& bg = c.scene->background;
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color), rhi::LoadOp::clear, {float(bg[0]), float(bg[1]), float(bg[2]), 1.0f}}};
    pass.depth = {c.view(t_.depth), rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(program_.pipeline);
    c.encoder.set_bind_group(0, c.bind_group(program_, {bind(scene_vert_shader::frame, frame_)}));
    if (shadowed_ || cloud_shadowed_) c.encoder.set_bind_group(2, c.bind_group(program_, set2(c)));
    geometry_->draw(c.encoder, 1);
    c.encoder.end_render_pass();
  }

 private:
  // Set 2 as wired: the shadow map (with the media's and the translucent casters' maps), the cloud shadow.
  std::vector<rhi::BoundResource> set2(PassContext& c) const {
    std::vector<rhi::BoundResource> shadow;
    if (cloud_shadowed_) {
      namespace shader = scene_cloud_shadow_shader;
      shadow = {bind(shader::cloud_shadow, c.view(t_.cloud_shadow)),
                bind(shader::cloud_shadow_sampler, c.sampler(rhi::StockSampler::linear_clamp)),
                bind(shader::cloud_shadow_view, c.buffer(t_.cloud_shadow_view))};
    }
    if (shadowed_) {
      namespace shader = scene_shadow_shader;
      shadow.push_back(bind(shader::shadow_depth, c.view(t_.shadow_map)));
      shadow.push_back(bind(shader::shadow_sampler, c.sampler(rhi::StockSampler::nearest_clamp)));
      shadow.push_back(bind(shader::shadow, c.buffer(t_.light_view)));
      if (media_shadowed_) {
        shadow.push_back(bind(shader::media_shadow, c.view(t_.media_shadow)));
        shadow.push_back(bind(shader::media_shadow_sampler, c.sampler(rhi::StockSampler::linear_clamp)));
      }
      if (translucent_shadowed_) {
        shadow.push_back(bind(shader::translucent_shadow, c.view(t_.translucent_shadow)));
        shadow.push_back(bind(shader::translucent_shadow_depth, c.view(t_.translucent_shadow_depth)));
      }
    }
    return shadow;
  }

  // Set 2 as wired: the shadow map, with the media's opacity map and the translucent casters' map, and the cloud shadow.
  const char* fragment_shader() const {
    if (!shadowed_) return cloud_shadowed_ ? "scene_cloud_shadowed.frag" : "scene.frag";
    if (media_shadowed_) {
      if (translucent_shadowed_) return cloud_shadowed_ ? "scene_media_translucent_shadowed_cloud_shadowed.frag" : "scene_media_translucent_shadowed.frag";
      return cloud_shadowed_ ? "scene_media_shadowed_cloud_shadowed.frag" : "scene_media_shadowed.frag";
    }
    if (translucent_shadowed_) return cloud_shadowed_ ? "scene_translucent_shadowed_cloud_shadowed.frag" : "scene_translucent_shadowed.frag";
    return cloud_shadowed_ ? "scene_shadowed_cloud_shadowed.frag" : "scene_shadowed.frag";
  }

  gpu::SceneFrame frame_of(PassContext& c) {
    const Scene& scene = *c.scene;
    const Extent size = c.extent(t_.color);
    return lighting_.scene_frame(scene, physics::view_projection(scene.camera, double(size.width) / size.height), c.param(t_.ambient));
  }

  const SceneTable& t_;
  bool shadowed_ = false, media_shadowed_ = false, translucent_shadowed_ = false, cloud_shadowed_ = false;
  plumbing::RenderProgram program_;
  rhi::BufferId frame_;
  std::unique_ptr<plumbing::SceneGeometry> geometry_;
  plumbing::SceneLighting lighting_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(SceneTable, SceneExecution);

}  // namespace volgraph
