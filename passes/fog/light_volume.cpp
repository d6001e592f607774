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
// Per frame, five render passes (private images, transitions recorded here):
// light_frame (the map's clip space back to the world), cells (the grid's depths),
// ends (per texel the unshadowed sums and t_end), faces (the shadow volume added to the
// sums), resolve (into fog_scattering, and the transmittance into fog_transmittance).
#include <array>
#include <cmath>
#include <span>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/fog/fog_passes.h"
#include "passes/fog/pixel_fog.h"
#include "passes/shading/camera.h"
#include "passes/shading/programs.h"
#include "passes/shading/shadow_view.h"

namespace volgraph {
namespace {

constexpr uint32_t kVerticesPerCell = 48;  // light_volume_faces.vert: 2 caps and 2 walls of 3 quads
constexpr uint32_t kLightFrameTexels = 5;  // light_volume.glsl LIGHT_FRAME_TEXELS
constexpr double kNearPlaneScale = 1e-3;   // the faces' near plane, a fraction of the camera's

// std140 mirror of light_volume.glsl's LightVolumeParams.
struct GpuLightVolumeParams {
  float camera_clip[16];
  int32_t sizes[4];
};

// World → the camera's clip space for the faces: x, y as the camera's projection, w the view
// depth (so 1/gl_FragCoord.w is the fragment's depth), z = w − n: clipped only in front of
// a near plane at n, with no far plane (a face behind the far plane still counts).
shading::Mat4 faces_clip(const Camera& camera, double aspect) {
  const double cot = 1.0 / std::tan(camera.fov_y_deg * M_PI / 360.0);
  shading::Mat4 p;
  p(0, 0) = cot / aspect;
  p(1, 1) = cot;
  p(2, 2) = -1;
  p(2, 3) = -kNearPlaneScale * camera.near;
  p(3, 2) = -1;
  return p * shading::look_at(camera.position, camera.target, camera.up);
}

// A private image of the pass: rendered to, then read by a later draw.
struct Image {
  rhi::TextureId texture;
  rhi::TextureViewId view;
};

Image make_image(rhi::Device& device, const std::string& label, Format format, Extent size) {
  const rhi::TextureId t = device.create_texture({label, ResourceKind::texture2d, format, size, rhi::texture_usage::attachment | rhi::texture_usage::sampled});
  return {t, device.create_view(t)};
}

const AccessState kRendered = access_state(Usage::color_attachment, PassKind::graphics, ResourceKind::texture2d);
const AccessState kBlended = access_state(Usage::color_attachment_load, PassKind::graphics, ResourceKind::texture2d);
const AccessState kReadByFaces = {stage::vertex_shader | stage::fragment_shader, access::shader_sampled_read, Layout::shader_read_only};

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

class LightVolumeExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!ends_.texture) prepare(c);
    transition({{light_frame_, {kReadByFaces.stages, kReadByFaces.access, Layout::undefined}, kRendered},
                {cells_, {kReadByFaces.stages, kReadByFaces.access, Layout::undefined}, kRendered},
                {ends_, {kReadByFaces.stages, kReadByFaces.access, Layout::undefined}, kRendered},
                {sums_, {kReadByFaces.stages, kReadByFaces.access, Layout::undefined}, kRendered}},
               c);
    if (shadowed_) {
      fullscreen(c, "light_frame", {light_frame_.view}, unproject_, unproject_group_);
      fullscreen(c, "cells", {cells_.view}, cells_program_, cells_group_);
    }
    fullscreen(c, "ends", {ends_.view, sums_.view}, ends_program_, ends_group_);
    transition({{light_frame_, kRendered, kReadByFaces}, {cells_, kRendered, kReadByFaces}, {ends_, kRendered, kReadByFaces},
                {sums_, kRendered, kBlended}},
               c);
    if (shadowed_) draw_faces(c);
    transition({{sums_, kBlended, kReadByFaces}}, c);
    fullscreen(c, "resolve", {c.view("fog_scattering"), c.view("fog_transmittance")}, resolve_, resolve_group_);
  }

 private:
  struct Transition {
    Image image;
    AccessState from, to;
  };

  static void transition(std::initializer_list<Transition> list, PassContext& c) {
    std::vector<rhi::ResourceBarrier> barriers;
    for (const Transition& t : list) barriers.push_back({t.image.texture, {}, t.from, t.to});
    c.encoder.barrier(barriers);
  }

  static void fullscreen(PassContext& c, const char* what, std::vector<rhi::TextureViewId> targets, const shading::RenderProgram& program,
                         rhi::BindGroupId group) {
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name + " " + what;
    for (const rhi::TextureViewId v : targets) pass.colors.push_back({v, rhi::LoadOp::clear});
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(program.pipeline);
    c.encoder.set_bind_group(0, group);
    c.encoder.draw(3);
    c.encoder.end_render_pass();
  }

  // The shadow volume's faces onto the sums (loaded), each adding ±I.
  void draw_faces(PassContext& c) const {
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name + " faces";
    pass.colors = {{sums_.view, rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(faces_.pipeline);
    c.encoder.set_bind_group(0, faces_group_);
    if (indices_) {
      c.encoder.set_index_buffer(indices_, rhi::IndexFormat::uint32);
      c.encoder.draw_indexed(face_vertices_);
    } else {
      c.encoder.draw(face_vertices_);
    }
    c.encoder.end_render_pass();
  }

  static shading::RenderProgram program(PassContext& c, std::vector<rhi::ColorTargetState> targets, const char* vertex, const char* fragment) {
    rhi::RenderPipelineDesc pd;
    pd.label = c.graph_pass().name + " " + fragment;
    pd.colors = std::move(targets);
    pd.cull = rhi::CullMode::none;
    return shading::create_render_program(c.device, pd, vertex, fragment);
  }

  rhi::BufferId uniform(PassContext& c, const std::string& label, std::span<const std::byte> bytes,
                        uint32_t usage = rhi::buffer_usage::uniform) const {
    const rhi::BufferId b = c.device.create_buffer({c.graph_pass().name + " " + label, bytes.size(), usage | rhi::buffer_usage::copy_dst});
    c.device.write_buffer(b, 0, bytes);
    return b;
  }

  // Where the shadow map's view comes from: the graph's light_view, or a block that
  // shadows no light.
  rhi::BufferId shadow_view(PassContext& c) const {
    if (shadowed_) return c.buffer("light_view");
    shading::ShadowViewBlock none{};
    none.params[3] = -1.0f;
    return uniform(c, "no shadow view", std::as_bytes(std::span(&none, 1)));
  }

  void prepare(PassContext& c) {
    using rhi::BindGroupEntry;
    shadowed_ = c.bound("shadow_map") && c.bound("light_view");
    const Extent size = c.desc("fog_scattering").extent;
    const Extent out = c.graph.output_size;
    const uint32_t resolution = shadowed_ ? c.desc("shadow_map").extent.width : 1;
    const uint32_t grid = std::max(2u, uint32_t(std::min<int64_t>(std::get<int64_t>(c.param("grid")), resolution)));
    const bool steps = c.variant() == "texel_steps";
    face_vertices_ = (grid + 1) * (grid + 1) * kVerticesPerCell;
    if (shadowed_ && !steps) {
      const std::vector<uint32_t> indices = height_field_indices(grid);
      face_vertices_ = uint32_t(indices.size());
      indices_ = uniform(c, "indices", std::as_bytes(std::span(indices)), rhi::buffer_usage::index);
    }

    GpuLightVolumeParams params{};
    shading::to_floats(faces_clip(c.scene->camera, double(out.width) / double(out.height)), params.camera_clip);
    params.sizes[0] = int32_t(grid);
    params.sizes[2] = int32_t(size.width);
    params.sizes[3] = int32_t(size.height);
    const rhi::BufferId params_buffer = uniform(c, "params", std::as_bytes(std::span(&params, 1)));
    fog::FogFrameInputs frame_inputs;
    frame_inputs.grid = size;
    frame_inputs.range = {c.scene->camera.near, c.scene->camera.far, shading::FroxelDistribution::linear};
    frame_inputs.ambient_radiance = fog::ambient_param(c);
    frame_inputs.jitter = false;
    const fog::GpuFogFrame frame = fog::make_fog_frame(c, frame_inputs);
    const rhi::BufferId frame_buffer = uniform(c, "frame", std::as_bytes(std::span(&frame, 1)));
    const rhi::SamplerId nearest = c.device.create_sampler({"nearest"});
    const rhi::BufferId view = shadow_view(c);
    const std::string& name = c.graph_pass().name;

    light_frame_ = make_image(c.device, name + " light_frame", Format::rgba32_float, {kLightFrameTexels, 1, 1});
    cells_ = make_image(c.device, name + " cells", Format::r32_float, {grid, grid, 1});
    ends_ = make_image(c.device, name + " ends", Format::rgba32_float, size);
    sums_ = make_image(c.device, name + " sums", Format::rgba32_float, size);

    ends_program_ = program(c, {{Format::rgba32_float}, {Format::rgba32_float}}, "fullscreen.vert", "light_volume_ends.frag");
    ends_group_ = c.device.create_bind_group({name + " ends", ends_program_.layouts[0],
                                              {BindGroupEntry::of(0, frame_buffer), BindGroupEntry::of(1, c.view("depth")),
                                               BindGroupEntry::of(2, nearest), BindGroupEntry::of(3, view), BindGroupEntry::of(4, params_buffer)}});
    resolve_ = program(c, {{c.desc("fog_scattering").format}, {c.desc("fog_transmittance").format}}, "fullscreen.vert",
                       "light_volume_resolve.frag");
    resolve_group_ = c.device.create_bind_group({name + " resolve", resolve_.layouts[0],
                                                 {BindGroupEntry::of(0, sums_.view), BindGroupEntry::of(1, ends_.view),
                                                  BindGroupEntry::of(2, nearest), BindGroupEntry::of(3, frame_buffer)}});
    if (!shadowed_) return;

    unproject_ = program(c, {{Format::rgba32_float}}, "fullscreen.vert", "light_volume_unproject.frag");
    unproject_group_ = c.device.create_bind_group({name + " light_frame", unproject_.layouts[0], {BindGroupEntry::of(0, view)}});
    cells_program_ = program(c, {{Format::r32_float}}, "fullscreen.vert", "light_volume_cells.frag");
    cells_group_ = c.device.create_bind_group({name + " cells", cells_program_.layouts[0],
                                               {BindGroupEntry::of(0, c.view("shadow_map")), BindGroupEntry::of(1, nearest),
                                                BindGroupEntry::of(2, view), BindGroupEntry::of(3, params_buffer)}});
    faces_ = program(c, {{Format::rgba32_float, rhi::BlendMode::additive}}, steps ? "light_volume_faces.vert" : "light_volume_surface.vert",
                     "light_volume_faces.frag");
    faces_group_ = c.device.create_bind_group({name + " faces", faces_.layouts[0],
                                               {BindGroupEntry::of(0, params_buffer), BindGroupEntry::of(1, cells_.view),
                                                BindGroupEntry::of(2, light_frame_.view), BindGroupEntry::of(3, nearest),
                                                BindGroupEntry::of(4, frame_buffer), BindGroupEntry::of(5, ends_.view)}});
  }

  bool shadowed_ = false;
  uint32_t face_vertices_ = 0;
  rhi::BufferId indices_;  // height_field: the surface's triangles
  Image light_frame_, cells_, ends_, sums_;
  shading::RenderProgram unproject_, cells_program_, ends_program_, faces_, resolve_;
  rhi::BindGroupId unproject_group_, cells_group_, ends_group_, faces_group_, resolve_group_;
};

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

SlotDecl fog_image(std::string name, std::string doc) {
  SlotDecl s = slot_out(std::move(name), ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float, SizeSpec::of_output(), std::move(doc));
  s.format_overridable = true;
  return s;
}

}  // namespace

PassDecl light_volume_pass() {
  PassDecl d;
  d.name = "light_volume";
  d.kind = PassKind::graphics;
  d.doc = "Volumetric shadows of the shadow map's light in homogeneous fog by polygonal light volumes (Billeter et al. 2010): "
          "the shadow volume's faces add the analytic in-scattering integral, exact with respect to the shadow map.";
  d.variants = {
      {"height_field", "Billeter et al.'s mesh: one vertex per cell, the surface interpolated between cells (fast; approximate at depth edges)"},
      {"texel_steps", "one flat cap per cell with walls between cells: the shadowed region exactly as the hard shadow lookup sees it"},
  };
  d.params = {
      param_int("grid", 256, 2, 8192, "cells", "cells per side of the grid over the shadow map (at most its resolution; texel_steps at its resolution: exact)"),
      param_vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the fog scatters (unshadowed)"),
  };
  SlotDecl depth = slot_in("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (d32; 1 where nothing was drawn)");
  depth.format = Format::d32_float;
  SlotDecl map = slot_optional_in("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map (none: no shadows)");
  map.format = Format::d32_float;
  d.slots = {depth, map, slot_optional_in("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view"),
             fog_image("fog_scattering", "in-scattered radiance toward the camera, rgb (W/(m²·sr))"),
             fog_image("fog_transmittance", "transmittance from the camera to the surface (or the far plane), rgb")};
  d.needs = feature_bit(SceneFeature::medium);
  d.check_scene = check_homogeneous_fog;
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new LightVolumeExecution()); };
  return d;
}

}  // namespace volgraph
