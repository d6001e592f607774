// scene_probe: the opaque scene seen from a point into a cube map (ResourceKind::texture_cube)
// — a dynamic environment probe (RTR4 §10.4.3) for what reflects or refracts the scene
// around it (translucency's `environment`). Each face is a step of its own (a 90° square
// view along the face's axis, mirrored as a cube's faces are: physics/cube_face.h
// face_view_projection), so the compiler plans the depth buffer's reuse between faces like
// any other barrier. The surfaces are lit as the scene pass lights them (scene.vert,
// scene.frag; the same lighting block, plumbing::SceneLighting::scene_frame), unshadowed: the
// shadow and media maps are views from the scene's camera's light setup, wired to the scene
// pass, not to this one (said in the docs). Where no surface is, the wired `sky` cube
// (sky_cube.cube) toward the texel's centre, else the scene's background.
// Shaders: scene.vert, scene.frag, fullscreen.vert, scene_probe_sky.frag.
#include <array>
#include <memory>
#include <string>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/scene_geometry.h"
#include "passes/plumbing/scene_lighting.h"
#include "passes/register_pass.h"
#include "physics/cube_face.h"
#include "shaders/bindings/scene.vert.h"
#include "shaders/bindings/scene_probe_sky.frag.h"

namespace volgraph {
namespace {

namespace scene_probe_vert_shader = shaders::scene_vert;
namespace scene_probe_sky_shader = shaders::scene_probe_sky_frag;

constexpr size_t kCubeFaces = 6;

struct SceneProbeTable : PassTable {
  SceneProbeTable()
      : PassTable("scene_probe", PassKind::graphics, "The opaque scene seen from a point into a cube map (a dynamic environment probe), the sky behind it.") {}
  // Variants.
  VariantHandle lambert = variant("lambert", "each face the scene pass's Lambertian surfaces from the probe (unshadowed), the sky cube or background behind");
  // Parameters.
  ParamHandle<std::array<double, 3>> position = vec3("position", {0, 1, 0}, -1e6, 1e6, "m", "where the probe sees from (the reflecting objects' centre, say)");
  ParamHandle<int64_t> size = integer("size", 128, 1, 2048, "texels", "each face's side");
  ParamHandle<double> near = number("near", 0.05, 1e-4, 1e3, "m", "the faces' near plane");
  ParamHandle<double> far = number("far", 200, 1e-2, 1e7, "m", "the faces' far plane");
  ParamHandle<std::array<double, 3>> ambient =
      vec3("ambient", {0, 0, 0}, 0, 1e6, "W/m²", "uniform irradiance added to every surface, as the scene pass's `ambient`");
  // Slots.
  SlotHandle sky = optional_input("sky", ResourceKind::texture_cube, Usage::sampled,
                                  "a cube of the sky (sky_cube.cube) behind the surfaces; else the scene's background");
  SlotHandle cube = output("cube", ResourceKind::texture_cube, Usage::color_attachment, Format::rgba16_float, SizeSpec::square_of(size),
                           "the radiance toward each texel's centre from `position`, faces +x, −x, +y, −y, +z, −z");
  SlotHandle depth = internal("depth", ResourceKind::texture2d, Format::d32_float, SizeSpec::square_of(size), "one face's depth, reused face after face");
  // Steps: one a face.
  std::array<StepHandle, kCubeFaces> faces = face_steps();

 private:
  std::array<StepHandle, kCubeFaces> face_steps() {
    std::array<StepHandle, kCubeFaces> steps;
    for (size_t f = 0; f < kCubeFaces; ++f) {
      // The first face's clear may discard the cube; the others keep the faces drawn before.
      const Usage drawn = f == 0 ? Usage::color_attachment : Usage::color_attachment_load;
      steps[f] = step("face_" + std::to_string(f), PassKind::graphics, {{cube, drawn}, {depth, Usage::depth_attachment}, {sky, Usage::sampled}});
    }
    return steps;
  }
};

class SceneProbeExecution final : public PassExecution {
 public:
  explicit SceneProbeExecution(const SceneProbeTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    using namespace rhi;
    RenderPipelineDesc surfaces;
    surfaces.label = s.name() + " surfaces";
    surfaces.vertex_buffers = {plumbing::SceneGeometry::vertex_layout()};
    surfaces.colors = {{s.desc(t_.cube).format, BlendMode::replace}};
    surfaces.depth = {Format::d32_float, true, CompareFunction::less};
    surfaces.cull = CullMode::none;             // planes are seen from both sides
    surfaces.front_counter_clockwise = false;  // the faces are mirrored: a front face winds clockwise on them
    surfaces_ = plumbing::create_render_program(s.device, surfaces, "scene.vert", "scene.frag");
    plumbing::check_wrapped_uniform_mirror<gpu::SceneFrame>(surfaces_, scene_probe_vert_shader::frame, s.name() + " frame");
    RenderPipelineDesc sky;
    sky.label = s.name() + " sky";
    sky.colors = {{s.desc(t_.cube).format, BlendMode::replace}};
    sky.depth = {Format::d32_float, false, CompareFunction::less_equal};  // only where no surface is (depth still 1)
    sky_ = plumbing::create_render_program(s.device, sky, "fullscreen.vert", "scene_probe_sky.frag");
    plumbing::check_wrapped_uniform_mirror<gpu::SceneProbeFace>(sky_, scene_probe_sky_shader::probe, s.name() + " face");
    for (size_t f = 0; f < kCubeFaces; ++f) {
      frames_[f] = s.device.create_buffer({s.name() + " frame " + std::to_string(f), sizeof(gpu::SceneFrame), buffer_usage::uniform | buffer_usage::copy_dst});
      const gpu::SceneProbeFace face{{float(f), float(s.extent(t_.cube).width), 0, 0}};
      face_blocks_[f] = plumbing::create_uniform_buffer(s.device, s.name() + " face " + std::to_string(f), std::as_bytes(std::span(&face, 1)));
    }
    geometry_ = std::make_unique<plumbing::SceneGeometry>(s.device, *s.scene, surfaces_);
  }

  void record(PassContext& c) override {
    const size_t f = face_of(c);
    const Scene& scene = *c.scene;
    const std::array<double, 3> p = c.param(t_.position);
    const physics::Mat4 view_projection = physics::cube::face_view_projection(int(f), {p[0], p[1], p[2]}, c.param(t_.near), c.param(t_.far));
    const gpu::SceneFrame frame = lighting_.scene_frame(scene, view_projection, c.param(t_.ambient));
    c.device.write_buffer(frames_[f], 0, std::as_bytes(std::span(&frame, 1)));
    const Vec3& background = scene.background;
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.face_view(t_.cube, uint32_t(f)), rhi::LoadOp::clear, {float(background[0]), float(background[1]), float(background[2]), 1.0f}}};
    pass.depth = {c.view(t_.depth), rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(surfaces_.pipeline);
    c.encoder.set_bind_group(0, c.bind_group(surfaces_, {bind(scene_probe_vert_shader::frame, frames_[f])}));
    geometry_->draw(c.encoder, 1);
    if (c.bound(t_.sky)) {
      namespace shader = scene_probe_sky_shader;
      c.encoder.set_pipeline(sky_.pipeline);
      c.encoder.set_bind_group(0, c.bind_group(sky_, {bind(shader::probe, face_blocks_[f]), bind(shader::sky, c.view(t_.sky)),
                                                      bind(shader::linear, c.sampler(rhi::StockSampler::linear_clamp))}));
      c.encoder.draw(3);  // fullscreen.vert's one triangle
    }
    c.encoder.end_render_pass();
  }

 private:
  size_t face_of(const PassContext& c) const {
    for (size_t f = 0; f < kCubeFaces; ++f) {
      if (c.step_is(t_.faces[f])) return f;
    }
    return 0;
  }

  const SceneProbeTable& t_;
  plumbing::RenderProgram surfaces_, sky_;
  std::array<rhi::BufferId, kCubeFaces> frames_, face_blocks_;
  std::unique_ptr<plumbing::SceneGeometry> geometry_;
  plumbing::SceneLighting lighting_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(SceneProbeTable, SceneProbeExecution);

}  // namespace volgraph
