// light_volume: volumetric shadows by polygonal light volumes (Billeter, Sintorn, Assarsson,
// "Real-time volumetric shadows using polygonal light volumes", HPG 2010), in the scene's
// homogeneous global fog. Along a camera ray the in-scattering of the shadowed light over
// any segment is I(t1) − I(t0), I(t) its unshadowed integral from the camera
// (shaders/include/light_volume_integral.glsl); so per pixel the pass takes every light's
// unshadowed integral to the surface and adds, for each face of the shadow map's shadow
// volume the ray crosses before the surface, +I(t) where it enters the shadow and −I(t)
// where it leaves (faces behind the surface add ±I(t_end), so a shadowed surface point
// ends the last shadowed segment there). Billeter et al. render the lit volume closed
// toward the light; here its complement inside the shadow map's frustum is rendered: the
// same signed sum, also exact where the shadow lookup calls points lit outside the
// map's window or beyond its far plane (a directional light's window covers only what
// the camera sees), and bounded on every side.
//
// The shadow volume is what the shadow map's hard lookup (shadow_lookup.glsl) calls
// shadowed: per cell of a `grid`×`grid` grid over the map, the light's rays through the
// cell from the cell's depth (+ the map's bias) to the map's far plane; a cell takes the
// depth of the texel under its centre (coarser grids see the map at the grid's
// resolution). Two meshes (variants):
// - height_field (default; Billeter et al. §4): one vertex per cell at its centre and
//   depth, the surface interpolated between cells, walls on the map's edges, a far cap
//   (light_volume_surface.vert, an index buffer): N² vertices, 2N² triangles. Between two
//   cells of different depth it is a slope where the lookup has a step, so it is off by
//   up to a cell at depth edges (measured in tests/gpu/light_volume_test.cpp);
// - texel_steps: each cell a flat cap, walls to its neighbours over the depths where one
//   is shadowed and the other not (light_volume_faces.vert): the volume the lookup sees,
//   exact with respect to the map when `grid` ≥ its resolution; 48 vertices a cell.
// The faces are drawn from the camera with depth test off, both faces, additively into
// an rgba32f image (blendable on both backends: Vulkan, and Dawn's float32-blendable).
//
// What it needs and gives: homogeneous global fog only (height fog or volumes: refused);
// the shadow map's light volumetrically shadowed, every other light (points, spots,
// directional) and the ambient and emission terms added unshadowed in closed form or by
// the same quadrature; the PCF variant of shadow_map is seen as its hard lookup; without a
// shadow map everything is unshadowed. Transmittance e^(−σt·t_end). Physics as
// raymarch_fog in a homogeneous medium with volumetric shadows on (the light toward a
// point or spot dimmed by e^(−σt·d), a directional light not).
//
// It runs as five steps, each a graph pass of its own (PassDecl::steps), over four
// internal images the graph allocates, aliases, synchronises and can dump
// (`--dump PASS.cells=…`): light_frame (the map's clip space back to the world), cells
// (the grid's depths), ends (per texel the unshadowed sums and t_end), faces (the shadow
// volume added to the sums), resolve (into fog_scattering, and the transmittance into
// fog_transmittance). Steps rather than one pass with its own barriers: each image is
// rendered by one draw and read by the next, and the compiler's unit of ordering and
// synchronisation is the graph pass, so as steps every transition is planned, checked
// by the plan checker and timed like any other.
#include <array>
#include <cmath>
#include <cstring>
#include <span>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/register_pass.h"
#include "passes/fog/pixel_fog.h"
#include "physics/camera.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/shadow_view.h"
#include "passes/uniform_mirrors.h"
#include "shaders/bindings/light_volume_cells.frag.h"
#include "shaders/bindings/light_volume_ends.frag.h"
#include "shaders/bindings/light_volume_faces.frag.h"
#include "shaders/bindings/light_volume_faces.vert.h"
#include "shaders/bindings/light_volume_resolve.frag.h"
#include "shaders/bindings/light_volume_unproject.frag.h"

namespace volgraph {
namespace {

namespace light_volume_unproject_shader = shaders::light_volume_unproject_frag;
namespace light_volume_cells_shader = shaders::light_volume_cells_frag;
namespace light_volume_ends_shader = shaders::light_volume_ends_frag;
// The faces' program: light_volume_faces.vert's names stand for light_volume_surface.vert's too (the same bindings).
namespace light_volume_faces_vert_shader = shaders::light_volume_faces_vert;
namespace light_volume_faces_frag_shader = shaders::light_volume_faces_frag;
namespace light_volume_resolve_shader = shaders::light_volume_resolve_frag;

constexpr uint32_t kVerticesPerCell = 48;  // light_volume_faces.vert: 2 caps and 2 walls of 3 quads
constexpr uint32_t kLightFrameTexels = 5;  // light_volume.glsl LIGHT_FRAME_TEXELS
constexpr double kNearPlaneScale = 1e-3;   // the faces' near plane, a fraction of the camera's

// World → the camera's clip space for the faces: x, y as the camera's projection, w the view
// depth (so 1/gl_FragCoord.w is the fragment's depth), z = w − n: clipped only in front of
// a near plane at n, with no far plane (a face behind the far plane still counts).
physics::Mat4 faces_clip(const Camera& camera, double aspect) {
  const double cot = 1.0 / std::tan(camera.fov_y_deg * M_PI / 360.0);
  physics::Mat4 p(0.0);  // m[col][row]
  p[0][0] = cot / aspect;
  p[1][1] = cot;
  p[2][2] = -1;
  p[3][2] = -kNearPlaneScale * camera.near;
  p[2][3] = -1;
  return p * physics::look_at(camera.position, camera.target, camera.up);
}

// The height_field variant's triangles over light_volume_surface.vert's vertices (n ≥ 2
// cells per side), each wound with its normal out of the shadowed region in light clip
// space (x right, y up, z away from the light): the surface (normal −z), the walls on the
// map's edges (outward), and the far cap (+z) as a fan from its top-left corner through
// every far vertex on the border, so no edge ends in the middle of another.
std::vector<uint32_t> height_field_indices(uint32_t n) {
  const auto surface = [n](uint32_t k, uint32_t l) { return l * n + k; };
  const auto far_top = [n](uint32_t k) { return n * n + k; };
  const auto far_bottom = [n](uint32_t k) { return n * n + n + k; };
  const auto far_left = [n](uint32_t l) { return n * n + 2 * n + l; };
  const auto far_right = [n](uint32_t l) { return n * n + 3 * n + l; };
  std::vector<uint32_t> i;
  auto triangle = [&i](uint32_t a, uint32_t b, uint32_t c) { i.insert(i.end(), {a, b, c}); };
  for (uint32_t l = 0; l + 1 < n; ++l) {
    for (uint32_t k = 0; k + 1 < n; ++k) {
      triangle(surface(k, l), surface(k + 1, l), surface(k + 1, l + 1));
      triangle(surface(k, l), surface(k + 1, l + 1), surface(k, l + 1));
    }
  }
  for (uint32_t k = 0; k + 1 < n; ++k) {
    triangle(surface(k, 0), far_top(k), far_top(k + 1));  // top edge (NDC y = +1): normal +y
    triangle(surface(k, 0), far_top(k + 1), surface(k + 1, 0));
    triangle(surface(k, n - 1), far_bottom(k + 1), far_bottom(k));  // bottom: −y
    triangle(surface(k, n - 1), surface(k + 1, n - 1), far_bottom(k + 1));
    triangle(surface(0, k), far_left(k + 1), far_left(k));  // left (x = −1): −x
    triangle(surface(0, k), surface(0, k + 1), far_left(k + 1));
    triangle(surface(n - 1, k), far_right(k), far_right(k + 1));  // right: +x
    triangle(surface(n - 1, k), far_right(k + 1), surface(n - 1, k + 1));
  }
  std::vector<uint32_t> border;  // counter-clockwise from the top-left corner
  for (uint32_t l = 0; l < n; ++l) border.push_back(far_left(l));
  for (uint32_t k = 1; k < n; ++k) border.push_back(far_bottom(k));
  for (uint32_t l = n - 1; l-- > 0;) border.push_back(far_right(l));
  for (uint32_t k = n - 1; k-- > 1;) border.push_back(far_top(k));
  for (size_t b = 1; b + 1 < border.size(); ++b) triangle(border[0], border[b], border[b + 1]);
  return i;
}

// The technique needs a homogeneous medium: the global fog and nothing else (one message).
std::vector<ParamProblem> check_homogeneous_fog(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  std::vector<std::string> others;
  if (scene.media.height_fog) others.push_back("media.height_fog");
  if (!scene.media.volumes.empty()) others.push_back(std::to_string(scene.media.volumes.size()) + " media.volumes");
  if (others.empty() && scene.media.fog) return {};
  const std::string has = others.empty() ? "no media.fog" : others.size() == 1 ? others[0] : others[0] + " and " + others[1];
  return {{"", "light_volume integrates along each ray in closed form and needs homogeneous media, the global media.fog only; "
               "the scene has " + has + " (use raymarch_fog or the froxel chain)"}};
}

struct LightVolumeTable : PassTable {
  LightVolumeTable()
      : PassTable("light_volume", PassKind::graphics,
                  "Volumetric shadows of the shadow map's light in homogeneous fog by polygonal light volumes (Billeter et al. 2010): "
                  "the shadow volume's faces add the analytic in-scattering integral, exact with respect to the shadow map.") {
    decl.needs = feature_bit(SceneFeature::medium);
    decl.check_scene = check_homogeneous_fog;
  }
  VariantHandle height_field = variant("height_field",
      "Billeter et al.'s mesh: one vertex per cell, the surface interpolated between cells (fast; approximate at depth edges)");
  VariantHandle texel_steps = variant("texel_steps",
      "one flat cap per cell with walls between cells: the shadowed region exactly as the hard shadow lookup sees it");
  ParamHandle<int64_t> grid = integer("grid", 256, 2, 8192, "cells",
      "cells per side of the grid over the shadow map (at most its resolution; texel_steps at its resolution: exact)");
  ParamHandle<std::array<double, 3>> ambient = vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the fog scatters (unshadowed)");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (d32; 1 where nothing was drawn)",
                           {.format = Format::d32_float});
  SlotHandle shadow_map = optional_input("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map (none: no shadows)",
                                         {.format = Format::d32_float});
  SlotHandle light_view = optional_input("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view");
  SlotHandle fog_scattering = fog_image("fog_scattering", "in-scattered radiance toward the camera, rgb (W/(m²·sr))");
  SlotHandle fog_transmittance = fog_image("fog_transmittance", "transmittance from the camera to the surface (or the far plane), rgb");
  // Internal images.
  SlotHandle light_frame = internal("light_frame", ResourceKind::texture2d, Format::rgba32_float, SizeSpec::fixed(kLightFrameTexels, 1),
                                    "the shadow map's clip space back to the world (light_volume.glsl)");
  SlotHandle cells = internal("cells", ResourceKind::texture2d, Format::r32_float, SizeSpec::square_of(grid),
                              "per cell of the grid the light depth where shadow starts (the first min(grid, map side)² texels)");
  SlotHandle ends = internal("ends", ResourceKind::texture2d, Format::rgba32_float, SizeSpec::of_output(), "per pixel t_end and the unshadowed sums' ends");
  SlotHandle sums = internal("sums", ResourceKind::texture2d, Format::rgba32_float, SizeSpec::of_output(), "per pixel the signed sum of I(t)");
  // Steps.
  StepHandle unproject = step("light_frame", PassKind::graphics, {{light_view, Usage::uniform_read}, {light_frame, Usage::color_attachment}});
  StepHandle cell_depths = step("cells", PassKind::graphics,
                                {{shadow_map, Usage::sampled}, {light_view, Usage::uniform_read}, {cells, Usage::color_attachment}});
  StepHandle ray_ends = step("ends", PassKind::graphics, {{depth, Usage::sampled}, {light_view, Usage::uniform_read},
                                                          {ends, Usage::color_attachment}, {sums, Usage::color_attachment}});
  StepHandle faces = step("faces", PassKind::graphics, {{cells, Usage::sampled}, {light_frame, Usage::sampled}, {ends, Usage::sampled},
                                                        {sums, Usage::color_attachment_load}});
  StepHandle resolve = step("resolve", PassKind::graphics, {{sums, Usage::sampled}, {ends, Usage::sampled},
                                                            {fog_scattering, Usage::color_attachment}, {fog_transmittance, Usage::color_attachment}});

 private:
  SlotHandle fog_image(std::string name, std::string doc) {
    return output(std::move(name), ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float, SizeSpec::of_output(),
                  std::move(doc), {.format_overridable = true});
  }
};

class LightVolumeExecution final : public PassExecution {
 public:
  explicit LightVolumeExecution(const LightVolumeTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    shadowed_ = s.bound(t_.shadow_map) && s.bound(t_.light_view);
    const Extent size = s.extent(t_.fog_scattering);
    const Extent out = s.frame_size();
    const uint32_t resolution = shadowed_ ? s.extent(t_.shadow_map).width : 1;
    const uint32_t grid = std::max(2u, uint32_t(std::min<int64_t>(s.param(t_.grid), resolution)));
    const bool steps = s.variant_is(t_.texel_steps);
    face_vertices_ = (grid + 1) * (grid + 1) * kVerticesPerCell;
    if (shadowed_ && !steps) {
      const std::vector<uint32_t> indices = height_field_indices(grid);
      face_vertices_ = uint32_t(indices.size());
      indices_ = buffer(s, "indices", std::as_bytes(std::span(indices)), rhi::buffer_usage::index);
    }
    gpu::LightVolumeParams params{};
    float camera_clip[16];
    physics::to_floats(faces_clip(s.scene->camera, double(out.width) / double(out.height)), camera_clip);
    std::memcpy(&params.camera_clip, camera_clip, sizeof(camera_clip));
    params.sizes[0] = int32_t(grid);
    params.sizes[2] = int32_t(size.width);
    params.sizes[3] = int32_t(size.height);
    params_ = buffer(s, "params", std::as_bytes(std::span(&params, 1)));
    fog::FogFrameInputs frame_inputs;
    frame_inputs.grid = size;
    frame_inputs.range = {s.scene->camera.near, s.scene->camera.far, physics::FroxelDistribution::linear};
    frame_inputs.ambient_radiance = s.param(t_.ambient);
    frame_inputs.jitter = false;
    const gpu::FogFrame frame = fog::make_fog_frame(s, 0, frame_inputs, lighting_);
    frame_ = buffer(s, "frame", std::as_bytes(std::span(&frame, 1)));
    if (!shadowed_) {
      plumbing::ShadowViewBlock none{};
      none.params[3] = -1.0f;  // shadows no light
      no_shadow_view_ = buffer(s, "no shadow view", std::as_bytes(std::span(&none, 1)));
    }
    ends_program_ = program(s, {{Format::rgba32_float}, {Format::rgba32_float}}, "fullscreen.vert", "light_volume_ends.frag");
    resolve_ = program(s, {{s.desc(t_.fog_scattering).format}, {s.desc(t_.fog_transmittance).format}}, "fullscreen.vert",
                       "light_volume_resolve.frag");
    if (shadowed_) {
      unproject_ = program(s, {{Format::rgba32_float}}, "fullscreen.vert", "light_volume_unproject.frag");
      cells_program_ = program(s, {{Format::r32_float}}, "fullscreen.vert", "light_volume_cells.frag");
      faces_ = program(s, {{Format::rgba32_float, rhi::BlendMode::additive}},
                       steps ? "light_volume_faces.vert" : "light_volume_surface.vert", "light_volume_faces.frag");
    }
    check_blocks(s);
  }

  void record(PassContext& c) override {
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    if (c.step_is(t_.unproject) && shadowed_) {
      namespace shader = light_volume_unproject_shader;
      fullscreen(c, {c.view(t_.light_frame)}, unproject_, c.bind_group(unproject_, {bind(shader::shadow, shadow_view(c))}));
    } else if (c.step_is(t_.cell_depths) && shadowed_) {
      namespace shader = light_volume_cells_shader;
      fullscreen(c, {c.view(t_.cells)}, cells_program_,
                 c.bind_group(cells_program_, {bind(shader::shadow_depth, c.view(t_.shadow_map)), bind(shader::nearest, nearest),
                                               bind(shader::shadow, shadow_view(c)), bind(shader::params, params_)}));
    } else if (c.step_is(t_.ray_ends)) {
      namespace shader = light_volume_ends_shader;
      fullscreen(c, {c.view(t_.ends), c.view(t_.sums)}, ends_program_,
                 c.bind_group(ends_program_, {bind(shader::frame, frame_), bind(shader::scene_depth, c.view(t_.depth)),
                                              bind(shader::nearest, nearest), bind(shader::shadow, shadow_view(c)), bind(shader::params, params_)}));
    } else if (c.step_is(t_.faces) && shadowed_) {
      namespace vert = light_volume_faces_vert_shader;
      namespace frag = light_volume_faces_frag_shader;
      draw_faces(c, c.bind_group(faces_, {bind(frag::params, params_), bind(vert::cells, c.view(t_.cells)),
                                          bind(frag::light_frame, c.view(t_.light_frame)), bind(frag::nearest, nearest),
                                          bind(frag::frame, frame_), bind(frag::ends, c.view(t_.ends))}));
    } else if (c.step_is(t_.resolve)) {
      namespace shader = light_volume_resolve_shader;
      fullscreen(c, {c.view(t_.fog_scattering), c.view(t_.fog_transmittance)}, resolve_,
                 c.bind_group(resolve_, {bind(shader::sums, c.view(t_.sums)), bind(shader::ends, c.view(t_.ends)),
                                         bind(shader::nearest, nearest), bind(shader::frame, frame_)}));
    }
  }

 private:
  // The blocks each step's shaders read (the params, the frame and the shadow view:
  // no_shadow_view_ or the graph's light_view) match their C++ mirrors.
  void check_blocks(const PassSetup& s) const {
    using plumbing::check_wrapped_uniform_mirror;
    const std::string params = s.pass_name() + " params", frame = s.pass_name() + " frame",
                      view = s.pass_name() + " shadow view";
    check_wrapped_uniform_mirror<gpu::FogFrame>(ends_program_, light_volume_ends_shader::frame, frame);
    check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(ends_program_, light_volume_ends_shader::shadow, view);
    check_wrapped_uniform_mirror<gpu::LightVolumeParams>(ends_program_, light_volume_ends_shader::params, params);
    check_wrapped_uniform_mirror<gpu::FogFrame>(resolve_, light_volume_resolve_shader::frame, frame);
    if (!shadowed_) return;
    check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(unproject_, light_volume_unproject_shader::shadow, view);
    check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(cells_program_, light_volume_cells_shader::shadow, view);
    check_wrapped_uniform_mirror<gpu::LightVolumeParams>(cells_program_, light_volume_cells_shader::params, params);
    check_wrapped_uniform_mirror<gpu::LightVolumeParams>(faces_, light_volume_faces_frag_shader::params, params);
    check_wrapped_uniform_mirror<gpu::FogFrame>(faces_, light_volume_faces_frag_shader::frame, frame);
  }

  static void fullscreen(PassContext& c, std::vector<rhi::TextureViewId> targets, const plumbing::RenderProgram& program,
                         rhi::BindGroupId group) {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    for (const rhi::TextureViewId v : targets) pass.colors.push_back({v, rhi::LoadOp::clear});
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(program.pipeline);
    c.encoder.set_bind_group(0, group);
    c.encoder.draw(3);
    c.encoder.end_render_pass();
  }

  // The shadow volume's faces onto the sums (loaded), each adding ±I.
  void draw_faces(PassContext& c, rhi::BindGroupId group) const {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.sums), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(faces_.pipeline);
    c.encoder.set_bind_group(0, group);
    if (indices_) {
      c.encoder.set_index_buffer(indices_, rhi::IndexFormat::uint32);
      c.encoder.draw_indexed(face_vertices_);
    } else {
      c.encoder.draw(face_vertices_);
    }
    c.encoder.end_render_pass();
  }

  static plumbing::RenderProgram program(PassSetup& s, std::vector<rhi::ColorTargetState> targets, const char* vertex, const char* fragment) {
    rhi::RenderPipelineDesc pd;
    pd.label = s.pass_name() + " " + fragment;
    pd.colors = std::move(targets);
    pd.cull = rhi::CullMode::none;
    return plumbing::create_render_program(s.device, pd, vertex, fragment);
  }

  static rhi::BufferId buffer(PassSetup& s, const std::string& label, std::span<const std::byte> bytes,
                              uint32_t usage = rhi::buffer_usage::uniform) {
    const rhi::BufferId b = s.device.create_buffer({s.pass_name() + " " + label, bytes.size(), usage | rhi::buffer_usage::copy_dst});
    s.device.write_buffer(b, 0, bytes);
    return b;
  }

  // Where the shadow map's view comes from: the graph's light_view, or a block that
  // shadows no light.
  rhi::BufferId shadow_view(const PassContext& c) const { return shadowed_ ? c.buffer(t_.light_view) : no_shadow_view_; }

  const LightVolumeTable& t_;
  bool shadowed_ = false;
  uint32_t face_vertices_ = 0;
  rhi::BufferId indices_;  // height_field: the surface's triangles
  plumbing::SceneLighting lighting_;
  rhi::BufferId params_, frame_, no_shadow_view_;
  plumbing::RenderProgram unproject_, cells_program_, ends_program_, faces_, resolve_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(LightVolumeTable, LightVolumeExecution);

}  // namespace volgraph
