// volume_visualize: a scalar 3D texture (volume_phantom's `density`) drawn over the scene
// (RTR4 14.3.1). The volume fills the world box of `center` and `extent` (a cube, or with
// `box: volume_data` the scene's volume file's proportions, sizes × spacing); each
// pixel's ray through it, clipped by the scene's depth, is either
//   raymarch:   marched front to back in `steps` equal steps with emission-absorption, each
//               sample's colour and opacity from the 1D transfer function (a preset table,
//               piecewise linear: shaders/include/volume_transfer.h), or with the optional
//               input `transfer_table` from that 2D table of density × |∇ρ| (Kniss et al.
//               2002; texels fetched whole, exact at its samples), the opacity corrected
//               for the step's length, α' = 1 − (1 − α)^(Δ/Δ₀) with Δ₀ = `opacity_length`;
//   isosurface: searched in `steps` equal steps for the first sample at or above `iso`,
//               the crossing refined by `bisections`, shaded by Lambert with the normal of
//               the density's gradient (central differences) lit by the scene's sun (else a
//               headlight of irradiance π), the transfer function's colour at `iso` as albedo.
//   slices:     `slices` view-aligned planes blended back to front (graphics step `slices`);
//   half_angle: `slices` planes across the half vector of the view and the light (Kniss et al.
//               2003), each drawn into the eye buffer lit by the light buffer's transmittance,
//               then into the light buffer; one graphics step alternating the two targets' render
//               passes with its own barriers (a step per slice cannot be: the count is a
//               parameter), then the eye buffer composited over the scene (record_half_angle).
// Output `color`: the scene's colour behind, times the volume's transmittance, plus what it
// emits (an isosurface is opaque). A compute pass that writes a new image, because fog_apply
// (the graph's compositor of scattering and transmittance) runs only with a medium or clouds
// in the scene, and a render target cannot be a storage image on WebGPU. Debug outputs (the
// isosurface's; zero elsewhere and in raymarch): `hit` (xyz the hit point, w 1) and
// `surface_normal` (xyz the unit normal, w 1). Shader: shaders/volume_visualize.comp.
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/sun_for_shader.h"
#include "passes/register_pass.h"
#include "passes/volume/volume_file_reader.h"
#include "physics/volume_transfer.h"
#include "physics/camera.h"
#include "shaders/bindings/volume_half_angle_composite.frag.h"
#include "shaders/bindings/volume_half_angle_eye.frag.h"
#include "shaders/bindings/volume_half_angle_light.frag.h"
#include "shaders/bindings/volume_slices.frag.h"
#include "shaders/bindings/volume_visualize.comp.h"
#include "shaders/bindings/volume_visualize_transfer_table.comp.h"

namespace volgraph {
namespace {

namespace volume_visualize_shader = shaders::volume_visualize_comp;

// The transfer function's table (physics/volume_transfer.h's presets).
enum class TransferPreset : uint8_t { shells, grey, constant };
// The box's shape: a cube, or the proportions of the scene's volume file (sizes × spacing).
enum class BoxShape : uint8_t { cube, volume_data };

std::vector<ParamProblem> volume_box_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params);

struct VolumeVisualizeTable : PassTable {
  VolumeVisualizeTable()
      : PassTable("volume_visualize", PassKind::compute,
                  "A scalar volume over the scene: ray marched with a 1D transfer function, or its isosurface (RTR4 14.3.1).") {
    decl.check_scene = volume_box_problems;
  }
  // Variants.
  VariantHandle raymarch = variant("raymarch", "front-to-back emission-absorption with the transfer function, opacity corrected per step",
                                   VOLUME_VISUALIZE_RAYMARCH);
  VariantHandle isosurface = variant("isosurface", "the first crossing of `iso`, refined by bisection, Lambert-shaded by the gradient's normal",
                                     VOLUME_VISUALIZE_ISOSURFACE);
  VariantHandle slices = variant("slices", "`slices` view-aligned slices through the box blended back to front (over), each sample's "
                                           "opacity corrected for the slices' spacing along its ray", VOLUME_VISUALIZE_SLICES);
  VariantHandle half_angle = variant("half_angle", "`slices` slices across the half vector of the view and the light (Kniss et al. 2003), "
                                                   "each lit by the light buffer's occlusion of the slices nearer the light",
                                     VOLUME_VISUALIZE_HALF_ANGLE);
  // Parameters.
  ParamHandle<std::array<double, 3>> center = vec3("center", {0, 1, 0}, -1e6, 1e6, "m", "the volume's box's centre");
  ParamHandle<double> extent = number("extent", 2, 1e-6, 1e6, "m", "the volume's box's side (its longest side when `box` is volume_data)");
  ChoiceHandle<BoxShape> box = choice("box", BoxShape::cube, {{BoxShape::cube, "cube"}, {BoxShape::volume_data, "volume_data"}},
                                      "the box's shape: a cube of side `extent`, or the scene's volume file's sizes × spacing, its longest side `extent`");
  ParamHandle<int64_t> steps = integer("steps", 128, 1, 4096, "", "equal steps over the ray's segment inside the box");
  ParamHandle<int64_t> slice_count = integer("slices", 128, 1, 4096, "",
                                             "slices: view-aligned planes over the box's view-depth range; half_angle: planes across the half vector");
  ParamHandle<int64_t> light_resolution = integer("light_resolution", 256, 1, 4096, "", "half_angle: the light buffer's side (texels)");
  ParamHandle<bool> light_occlusion = flag("light_occlusion", true, "half_angle: the slices nearer the light shadow the rest (off: unshadowed)");
  ParamHandle<int64_t> bisections = integer("bisections", 8, 0, 32, "", "isosurface: halvings of the step where the density crosses `iso`");
  ParamHandle<double> iso = number("iso", 0.5, 0, 1, "", "isosurface: the density of the surface");
  ParamHandle<double> opacity_length = number("opacity_length", 0.02, 1e-6, 1e6, "m",
                                              "Δ₀: the step length for which the transfer function's opacity holds");
  ChoiceHandle<TransferPreset> transfer = choice(
      "transfer", TransferPreset::shells,
      {{TransferPreset::shells, "shells"}, {TransferPreset::grey, "grey"}, {TransferPreset::constant, "constant"}},
      "the transfer function's table: shells (hats at the shells phantom's densities), grey (a ramp), constant (`color`, `opacity`)");
  ParamHandle<double> gradient_low = number("gradient_low", 0, 0, 1e9, "1/m",
                                            "the 2D transfer (Kniss et al. 2002): |∇ρ| below which a sample is transparent");
  ParamHandle<double> gradient_high = number("gradient_high", 0, 0, 1e9, "1/m",
                                             "the 2D transfer: |∇ρ| from which the table's opacity holds in full (0: off, the 1D table)");
  ParamHandle<double> gradient_max = number("gradient_max", 10, 1e-9, 1e9, "1/m",
                                             "with a transfer_table: the |∇ρ| of the table's top row (its bottom row 0)");
  ParamHandle<std::array<double, 3>> color = vec3("color", {1, 1, 1}, 0, 1e6, "", "transfer constant: the colour at every density");
  ParamHandle<double> opacity = number("opacity", 0.1, 0, 1, "", "transfer constant: the opacity per opacity_length at every density");
  // Slots.
  SlotHandle density = input("density", ResourceKind::texture3d, Usage::sampled, "volume_phantom.density: r the density in the unit box");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth: the rays end there", {.format = Format::d32_float});
  SlotHandle scene_color = input("scene_color", ResourceKind::texture2d, Usage::sampled, "the scene's linear radiance, behind the volume");
  SlotHandle transfer_table = optional_input("transfer_table", ResourceKind::texture2d, Usage::sampled,
                                             "raymarch: transfer_table.table, the full 2D transfer (density × |∇ρ| up to gradient_max) "
                                             "in place of `transfer` and the gradient ramp (unbound: those)",
                                             {.format = Format::rgba8_unorm, .read_in = {raymarch}});
  SlotHandle color_out = output("color", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                                "the scene's radiance seen through the volume (the frame's size, as its scene_color)");
  SlotHandle hit = output("hit", ResourceKind::texture2d, Usage::storage_write, Format::rgba32_float, SizeSpec::of_output(),
                          "isosurface: xyz the hit point (m), w 1 where the ray meets the surface (0 elsewhere and in raymarch)");
  SlotHandle surface_normal = output("surface_normal", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                     SizeSpec::of_output(), "isosurface: xyz the surface's unit normal, w 1 where hit (0 elsewhere)");
  SlotHandle eye = internal("eye", ResourceKind::texture2d, Format::rgba16_float, SizeSpec::of_output(),
                            "half_angle: the slices' premultiplied radiance and opacity, composited over `color` last");
  SlotHandle light = internal("light", ResourceKind::texture2d, Format::rgba16_float, SizeSpec::square_of(light_resolution),
                              "half_angle: the light buffer, the transmittance from the light through the slices drawn so far");
  // Steps: the compute step (raymarch and isosurface draw there; slices and half_angle copy the
  // scene behind), then slices' planes drawn over its colour, or half_angle's slices into the eye
  // and light buffers and the eye buffer composited over the colour.
  StepHandle volume = step("volume", PassKind::compute,
                           {{density, Usage::sampled}, {depth, Usage::sampled}, {scene_color, Usage::sampled}, {transfer_table, Usage::sampled},
                            {color_out, Usage::storage_write}, {hit, Usage::storage_write}, {surface_normal, Usage::storage_write}});
  StepHandle slice_planes = step("slices", PassKind::graphics,
                                 {{density, Usage::sampled}, {depth, Usage::sampled}, {color_out, Usage::color_attachment_load}},
                                 only_in({slices}));
  StepHandle light_clear = step("light_clear", PassKind::graphics, {{light, Usage::color_attachment}}, only_in({half_angle}));
  // The light buffer is sampled here, and between the eye's slices a target (the record's own barriers).
  StepHandle half_angle_slices = step("half_angle", PassKind::graphics,
                                      {{density, Usage::sampled}, {depth, Usage::sampled}, {eye, Usage::color_attachment_load},
                                       {light, Usage::sampled}},
                                      only_in({half_angle}));
  StepHandle half_angle_composite = step("half_angle_composite", PassKind::graphics,
                                         {{eye, Usage::sampled}, {color_out, Usage::color_attachment_load}}, only_in({half_angle}));
};

// `box: volume_data` needs the scene's volume file, whose header must read.
std::vector<ParamProblem> volume_box_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params) {
  static const VolumeVisualizeTable table;
  if (param_in(params, table.box.text) != "volume_data") return {};
  if (!scene.volume_data) return {{param_name(decl, table.box.text), "volume_data needs scene.volume_data (a NRRD or .raw file)"}};
  try {
    volume_file::volume_layout(*scene.volume_data);
  } catch (const volume_file::VolumeFileError& e) {
    return {{param_name(decl, table.box.text), e.what()}};
  }
  return {};
}

// Half the box's sides (m): a cube of side `extent`, or the volume file's proportions, its longest side `extent`.
std::array<double, 3> box_half_sides(BoxShape shape, double extent, const Scene& scene) {
  std::array<double, 3> proportions{1, 1, 1};
  if (shape == BoxShape::volume_data) proportions = volume_file::box_proportions(volume_file::volume_layout(*scene.volume_data));
  return {0.5 * extent * proportions[0], 0.5 * extent * proportions[1], 0.5 * extent * proportions[2]};
}

physics::volume_transfer::TransferTable transfer_table(TransferPreset preset, const std::array<double, 3>& colour, double opacity) {
  namespace vt = physics::volume_transfer;
  switch (preset) {
    case TransferPreset::grey: return vt::grey_transfer();
    case TransferPreset::constant: return vt::constant_transfer(glm::vec3(colour[0], colour[1], colour[2]), float(opacity));
    case TransferPreset::shells: break;
  }
  return vt::shells_transfer();
}

gpu::vec4 gpu_vec4(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }

class VolumeVisualizeExecution final : public PassExecution {
 public:
  explicit VolumeVisualizeExecution(const VolumeVisualizeTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    tabulated_ = s.bound(t_.transfer_table);
    program_ = plumbing::create_compute_program(s.device, tabulated_ ? "volume_visualize_transfer_table.comp" : "volume_visualize.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::VolumeVisualizeParams>(program_, volume_visualize_shader::params, s.name() + " params");
    params_ = s.device.create_buffer(
        {s.name() + " params", sizeof(gpu::VolumeVisualizeParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    if (s.variant_is(t_.half_angle)) return setup_half_angle(s);
    if (!s.variant_is(t_.slices)) return;
    rhi::RenderPipelineDesc pipeline;
    pipeline.label = s.name() + " slices";
    pipeline.colors = {{s.desc(t_.color_out).format, rhi::BlendMode::premultiplied_over}};
    slices_ = plumbing::create_render_program(s.device, pipeline, "volume_slices.vert", "volume_slices.frag");
  }

  void record(PassContext& c) override {
    if (c.step_is(t_.slice_planes)) return record_slices(c);
    if (c.step_is(t_.light_clear)) return record_light_clear(c);
    if (c.step_is(t_.half_angle_slices)) return record_half_angle(c);
    if (c.step_is(t_.half_angle_composite)) return record_half_angle_composite(c);
    namespace shader = volume_visualize_shader;
    const gpu::VolumeVisualizeParams params = visualize_params(c);
    front_to_back_ = params.half_angle_mode.x > 0.5f;
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    std::vector<rhi::BoundResource> entries = {
        bind(shader::params, params_), bind(shader::density, c.view(t_.density)),
        bind(shader::density_sampler, c.sampler(rhi::StockSampler::linear_clamp)), bind(shader::scene_depth, c.view(t_.depth)),
        bind(shader::scene_color, c.view(t_.scene_color)), bind(shader::nearest, nearest), bind(shader::color, c.view(t_.color_out)),
        bind(shader::hit, c.view(t_.hit)), bind(shader::surface_normal, c.view(t_.surface_normal))};
    if (tabulated_) entries.push_back(bind(shaders::volume_visualize_transfer_table_comp::transfer_table, c.view(t_.transfer_table)));
    const rhi::BindGroupId group = c.bind_group(program_, entries);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.color_out));
  }

 private:
  void setup_half_angle(PassSetup& s) {
    const auto program = [&](const char* what, const char* vertex, const char* fragment, Format format, rhi::BlendMode blend) {
      rhi::RenderPipelineDesc pipeline;
      pipeline.label = s.name() + " " + what;
      pipeline.colors = {{format, blend}};
      return plumbing::create_render_program(s.device, pipeline, vertex, fragment);
    };
    const char* slice_vertex = "volume_half_angle.vert";
    eye_over_ = program("eye slices (over)", slice_vertex, "volume_half_angle_eye.frag", Format::rgba16_float, rhi::BlendMode::premultiplied_over);
    eye_under_ = program("eye slices (under)", slice_vertex, "volume_half_angle_eye.frag", Format::rgba16_float, rhi::BlendMode::premultiplied_under);
    light_slices_ = program("light slices", slice_vertex, "volume_half_angle_light.frag", Format::rgba16_float, rhi::BlendMode::multiply);
    composite_ = program("composite", "fullscreen.vert", "volume_half_angle_composite.frag", s.desc(t_.color_out).format,
                         rhi::BlendMode::premultiplied_over);
  }

  // The light buffer's transmittance 1 before the first slice.
  void record_light_clear(PassContext& c) {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.light), rhi::LoadOp::clear, {1, 1, 1, 1}}};
    c.encoder.begin_render_pass(pass);
    c.encoder.end_render_pass();
  }

  // Half-angle slicing (Kniss et al. 2003): one graphics step whose render passes alternate, per
  // slice from the light on, the eye buffer (slice k lit by the light buffer) and the light buffer
  // (slice k's opacity multiplied in), with its own barriers between them: the light buffer,
  // sampled as the step declares, a target for its slice and back; the eye buffer target →
  // target between its passes. Not a graph step per slice: the slice count is a parameter up to
  // 4096, and a pass type declares its steps once.
  void record_half_angle(PassContext& c) {
    namespace eye_shader = shaders::volume_half_angle_eye_frag;
    namespace light_shader = shaders::volume_half_angle_light_frag;
    const plumbing::RenderProgram& eye_program = front_to_back_ ? eye_under_ : eye_over_;
    const rhi::SamplerId linear = c.sampler(rhi::StockSampler::linear_clamp);
    const rhi::BindGroupId eye_group =
        c.bind_group(eye_program, {bind(eye_shader::params, params_), bind(eye_shader::density, c.view(t_.density)),
                                   bind(eye_shader::density_sampler, linear), bind(eye_shader::scene_depth, c.view(t_.depth)),
                                   bind(eye_shader::light_buffer, c.view(t_.light)),
                                   bind(eye_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))});
    const rhi::BindGroupId light_group = c.bind_group(light_slices_, {bind(light_shader::params, params_), bind(light_shader::density, c.view(t_.density)),
                                                                     bind(light_shader::density_sampler, linear)});
    const AccessState target = access_state(Usage::color_attachment_load, PassKind::graphics, ResourceKind::texture2d);
    const AccessState sampled = access_state(Usage::sampled, PassKind::graphics, ResourceKind::texture2d);
    const rhi::TextureId eye = c.texture(t_.eye), light = c.texture(t_.light);
    const auto render_pass = [&](const char* what, SlotHandle slot, rhi::LoadOp load) {
      rhi::RenderPassDesc pass;
      pass.label = c.name() + " " + what;
      pass.colors = {{c.view(slot), load}};
      c.encoder.begin_render_pass(pass);
    };
    const uint32_t count = uint32_t(c.param(t_.slice_count));
    if (!c.param(t_.light_occlusion)) {  // unshadowed: every slice in one render pass, in order (the light buffer stays 1)
      render_pass("eye slices", t_.eye, rhi::LoadOp::clear);
      c.encoder.set_pipeline(eye_program.pipeline);
      c.encoder.set_bind_group(0, eye_group);
      c.encoder.draw(3 * count);
      c.encoder.end_render_pass();
      return;
    }
    for (uint32_t k = 0; k < count; ++k) {
      if (k > 0) {
        const std::array<rhi::ResourceBarrier, 2> to_eye = {{{.texture = light, .from = target, .to = sampled}, {.texture = eye, .from = target, .to = target}}};
        c.encoder.barrier(to_eye);
      }
      render_pass("eye slice", t_.eye, k == 0 ? rhi::LoadOp::clear : rhi::LoadOp::load);  // cleared to 0: nothing in front yet
      c.encoder.set_pipeline(eye_program.pipeline);
      c.encoder.set_bind_group(0, eye_group);
      c.encoder.draw(3, 1, 3 * k);  // volume_half_angle.vert: vertices 3k … 3k + 2 are slice k
      c.encoder.end_render_pass();
      const std::array<rhi::ResourceBarrier, 1> to_light = {{{.texture = light, .from = sampled, .to = target}}};
      c.encoder.barrier(to_light);
      render_pass("light slice", t_.light, rhi::LoadOp::load);
      c.encoder.set_pipeline(light_slices_.pipeline);
      c.encoder.set_bind_group(0, light_group);
      c.encoder.draw(3, 1, 3 * k);
      c.encoder.end_render_pass();
    }
    const std::array<rhi::ResourceBarrier, 1> to_sampled = {{{.texture = light, .from = target, .to = sampled}}};
    if (count > 0) c.encoder.barrier(to_sampled);  // as the step declares it, for the plan's next barrier
  }

  // The eye buffer over the compute step's copy of the scene.
  void record_half_angle_composite(PassContext& c) {
    namespace shader = shaders::volume_half_angle_composite_frag;
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color_out), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(composite_.pipeline);
    c.encoder.set_bind_group(0, c.bind_group(composite_, {bind(shader::eye, c.view(t_.eye)),
                                                          bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))}));
    c.encoder.draw(3);
    c.encoder.end_render_pass();
  }

  // The slices back to front over the compute step's copy of the scene (the params block it wrote).
  void record_slices(PassContext& c) {
    namespace shader = shaders::volume_slices_frag;
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color_out), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(slices_.pipeline);
    c.encoder.set_bind_group(0, c.bind_group(slices_, {bind(shader::params, params_), bind(shader::density, c.view(t_.density)),
                                                       bind(shader::density_sampler, c.sampler(rhi::StockSampler::linear_clamp)),
                                                       bind(shader::scene_depth, c.view(t_.depth)),
                                                       bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))}));
    c.encoder.draw(3, uint32_t(c.param(t_.slice_count)));  // volume_slices.vert: one triangle a slice
    c.encoder.end_render_pass();
  }

  // The slices' planes: `slices` of them, equally spaced over the box's view-depth range
  // (its corners' depths, from the near plane on), the farthest first.
  static void place_slices(const Scene& scene, const std::array<double, 3>& centre, const std::array<double, 3>& half, int64_t count,
                           gpu::VolumeVisualizeParams& p) {
    const Vec3 forward = physics::normalize(physics::sub(scene.camera.target, scene.camera.position));
    double nearest = 1e30, farthest = -1e30;
    for (int corner = 0; corner < 8; ++corner) {
      Vec3 q{};
      for (size_t i = 0; i < 3; ++i) q[i] = centre[i] + ((corner >> i) & 1 ? half[i] : -half[i]);
      const double z = physics::dot(physics::sub(q, scene.camera.position), forward);
      nearest = std::min(nearest, z), farthest = std::max(farthest, z);
    }
    nearest = std::max(nearest, scene.camera.near);
    const double spacing = std::max(farthest - nearest, 0.0) / double(std::max<int64_t>(count, 1));
    p.march.x = int32_t(count);
    p.surface.z = float(spacing);
    p.surface.w = float(farthest - 0.5 * spacing);
  }

  // Half-angle slices (Kniss et al. 2003; GPU Gems ch. 39 §39.5.1): the axis s halfway between the
  // view direction v and the light's direction of travel −l when the light is behind the eye
  // (v·l < 0: drawn front to back, blended under), else between −v and −l (back to front, over);
  // either way the slices go from the light outward, `count` of them over the box's corners' range
  // of s·p. Without a sun the light is a headlight from the camera of irradiance 4π, so that an
  // unoccluded sample emits its transfer colour, as in `slices`. The light buffer looks along l
  // at the box's bounding sphere.
  static void place_half_angle_slices(const Scene& scene, const std::array<double, 3>& centre, const std::array<double, 3>& half,
                                      int64_t count, int64_t light_side, bool occlusion, gpu::VolumeVisualizeParams& p) {
    const Vec3 view = physics::normalize(physics::sub(scene.camera.target, scene.camera.position));
    if (p.light_direction.w != 1.0f) {
      p.light_direction = {float(-view[0]), float(-view[1]), float(-view[2]), 0.0f};
      p.light_irradiance = {float(4 * M_PI), float(4 * M_PI), float(4 * M_PI), 0.0f};
    }
    const Vec3 toward_light = physics::normalize(Vec3{p.light_direction.x, p.light_direction.y, p.light_direction.z});
    const bool front_to_back = physics::dot(view, toward_light) < 0;
    const Vec3 axis = physics::normalize(front_to_back ? physics::sub(view, toward_light) : physics::scaled(physics::add(view, toward_light), -1));
    double lowest = 1e30, highest = -1e30;
    for (int corner = 0; corner < 8; ++corner) {
      Vec3 q{};
      for (size_t i = 0; i < 3; ++i) q[i] = centre[i] + ((corner >> i) & 1 ? half[i] : -half[i]);
      const double d = physics::dot(q, axis);
      lowest = std::min(lowest, d), highest = std::max(highest, d);
    }
    const double spacing = (highest - lowest) / double(std::max<int64_t>(count, 1));
    const Vec3 helper = std::abs(toward_light[1]) < 0.9 ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    const Vec3 u = physics::normalize(physics::cross(helper, toward_light)), w = physics::cross(toward_light, u);
    const double radius = std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
    p.march.x = int32_t(count);
    p.surface.z = float(spacing);
    p.half_axis = {float(axis[0]), float(axis[1]), float(axis[2]), float(lowest)};
    p.light_u = {float(u[0]), float(u[1]), float(u[2]), float(radius)};
    p.light_v = {float(w[0]), float(w[1]), float(w[2]), float(light_side)};
    p.half_angle_mode = {front_to_back ? 1.0f : 0.0f, occlusion ? 1.0f : 0.0f, 0, 0};
  }

  gpu::VolumeVisualizeParams visualize_params(const PassContext& c) const {
    const Scene& scene = *c.scene;
    gpu::VolumeVisualizeParams p{};
    p.view = fog::pack_view_rays(scene.camera, c.extent(t_.color_out));
    const std::array<double, 3> centre = c.param(t_.center);
    const std::array<double, 3> half = box_half_sides(c.param(t_.box), c.param(t_.extent), scene);
    for (size_t i = 0; i < 3; ++i) {
      p.box_min[int(i)] = float(centre[i] - half[i]);
      p.box_max[int(i)] = float(centre[i] + half[i]);
    }
    const physics::volume_transfer::TransferTable table = transfer_table(c.param(t_.transfer), c.param(t_.color), c.param(t_.opacity));
    p.march = {int32_t(c.param(t_.steps)), int32_t(c.param(t_.bisections)), table.count, c.variant().shader_code};
    p.surface = {float(c.param(t_.iso)), float(c.param(t_.opacity_length)), 0, 0};
    p.gradient = {float(c.param(t_.gradient_low)), float(c.param(t_.gradient_high)), float(c.param(t_.gradient_max)), 0};
    plumbing::write_sun_for_shader(scene, p.light_direction, p.light_irradiance);
    if (c.variant_is(t_.slices)) place_slices(scene, centre, half, c.param(t_.slice_count), p);
    if (c.variant_is(t_.half_angle))
      place_half_angle_slices(scene, centre, half, c.param(t_.slice_count), c.param(t_.light_resolution), c.param(t_.light_occlusion), p);
    for (int i = 0; i < VOLUME_TRANSFER_MAX_KNOTS; ++i) {
      p.knot_density[i] = gpu_vec4(table.density[size_t(i)]);
      p.knot_rgba[i] = gpu_vec4(table.rgba[size_t(i)]);
    }
    return p;
  }

  const VolumeVisualizeTable& t_;
  plumbing::ComputeProgram program_;
  plumbing::RenderProgram slices_;  // the variant slices' planes
  // half_angle's programs: the eye's slices blended over (back to front) or under (front to back),
  // the light's slices, the eye buffer's composite over the scene.
  plumbing::RenderProgram eye_over_, eye_under_, light_slices_, composite_;
  bool front_to_back_ = false;      // half_angle: this frame's order (the compute step's params)
  bool tabulated_ = false;          // the transfer_table input bound: volume_visualize_transfer_table.comp
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VolumeVisualizeTable, VolumeVisualizeExecution);

}  // namespace volgraph
