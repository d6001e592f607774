// volume_visualize: a scalar 3D texture (volume_phantom's `density`) drawn over the scene
// (RTR4 14.3.1). The volume fills the world box of `center` and `extent` (a cube); each
// pixel's ray through it, clipped by the scene's depth, is either
//   raymarch:   marched front to back in `steps` equal steps with emission-absorption, each
//               sample's colour and opacity from the 1D transfer function (a preset table,
//               piecewise linear: shaders/include/volume_transfer.h), the opacity corrected
//               for the step's length, α' = 1 − (1 − α)^(Δ/Δ₀) with Δ₀ = `opacity_length`;
//   isosurface: searched in `steps` equal steps for the first sample at or above `iso`,
//               the crossing refined by `bisections`, shaded by Lambert with the normal of
//               the density's gradient (central differences) lit by the scene's sun (else a
//               headlight of irradiance π), the transfer function's colour at `iso` as albedo.
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

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "physics/volume_transfer.h"
#include "shaders/bindings/volume_visualize.comp.h"

namespace volgraph {
namespace {

namespace volume_visualize_shader = shaders::volume_visualize_comp;

// The transfer function's table (physics/volume_transfer.h's presets).
enum class TransferPreset : uint8_t { shells, grey, constant };

struct VolumeVisualizeTable : PassTable {
  VolumeVisualizeTable()
      : PassTable("volume_visualize", PassKind::compute,
                  "A scalar volume over the scene: ray marched with a 1D transfer function, or its isosurface (RTR4 14.3.1).") {}
  // Variants.
  VariantHandle raymarch = variant("raymarch", "front-to-back emission-absorption with the transfer function, opacity corrected per step",
                                   VOLUME_VISUALIZE_RAYMARCH);
  VariantHandle isosurface = variant("isosurface", "the first crossing of `iso`, refined by bisection, Lambert-shaded by the gradient's normal",
                                     VOLUME_VISUALIZE_ISOSURFACE);
  // Parameters.
  ParamHandle<std::array<double, 3>> center = vec3("center", {0, 1, 0}, -1e6, 1e6, "m", "the volume's box's centre");
  ParamHandle<double> extent = number("extent", 2, 1e-6, 1e6, "m", "the volume's box's side (a cube)");
  ParamHandle<int64_t> steps = integer("steps", 128, 1, 4096, "", "equal steps over the ray's segment inside the box");
  ParamHandle<int64_t> bisections = integer("bisections", 8, 0, 32, "", "isosurface: halvings of the step where the density crosses `iso`");
  ParamHandle<double> iso = number("iso", 0.5, 0, 1, "", "isosurface: the density of the surface");
  ParamHandle<double> opacity_length = number("opacity_length", 0.02, 1e-6, 1e6, "m",
                                              "Δ₀: the step length for which the transfer function's opacity holds");
  ChoiceHandle<TransferPreset> transfer = choice(
      "transfer", TransferPreset::shells,
      {{TransferPreset::shells, "shells"}, {TransferPreset::grey, "grey"}, {TransferPreset::constant, "constant"}},
      "the transfer function's table: shells (hats at the shells phantom's densities), grey (a ramp), constant (`color`, `opacity`)");
  ParamHandle<std::array<double, 3>> color = vec3("color", {1, 1, 1}, 0, 1e6, "", "transfer constant: the colour at every density");
  ParamHandle<double> opacity = number("opacity", 0.1, 0, 1, "", "transfer constant: the opacity per opacity_length at every density");
  // Slots.
  SlotHandle density = input("density", ResourceKind::texture3d, Usage::sampled, "volume_phantom.density: r the density in the unit box");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth: the rays end there", {.format = Format::d32_float});
  SlotHandle scene_color = input("scene_color", ResourceKind::texture2d, Usage::sampled, "the scene's linear radiance, behind the volume");
  SlotHandle color_out = output_like("color", scene_color, Usage::storage_write, "the scene's radiance seen through the volume");
  SlotHandle hit = output("hit", ResourceKind::texture2d, Usage::storage_write, Format::rgba32_float, SizeSpec::of_output(),
                          "isosurface: xyz the hit point (m), w 1 where the ray meets the surface (0 elsewhere and in raymarch)");
  SlotHandle surface_normal = output("surface_normal", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                     SizeSpec::of_output(), "isosurface: xyz the surface's unit normal, w 1 where hit (0 elsewhere)");
};

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
    program_ = plumbing::create_compute_program(s.device, "volume_visualize.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::VolumeVisualizeParams>(program_, volume_visualize_shader::params, s.name() + " params");
    params_ = s.device.create_buffer(
        {s.name() + " params", sizeof(gpu::VolumeVisualizeParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    namespace shader = volume_visualize_shader;
    const gpu::VolumeVisualizeParams params = visualize_params(c);
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::params, params_), bind(shader::density, c.view(t_.density)),
                   bind(shader::density_sampler, c.sampler(rhi::StockSampler::linear_clamp)), bind(shader::scene_depth, c.view(t_.depth)),
                   bind(shader::scene_color, c.view(t_.scene_color)), bind(shader::nearest, nearest),
                   bind(shader::color, c.view(t_.color_out)), bind(shader::hit, c.view(t_.hit)),
                   bind(shader::surface_normal, c.view(t_.surface_normal))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.color_out));
  }

 private:
  gpu::VolumeVisualizeParams visualize_params(const PassContext& c) const {
    const Scene& scene = *c.scene;
    gpu::VolumeVisualizeParams p{};
    p.view = fog::pack_view_rays(scene.camera, c.extent(t_.color_out));
    const std::array<double, 3> centre = c.param(t_.center);
    const double half = 0.5 * c.param(t_.extent);
    for (int i = 0; i < 3; ++i) {
      p.box_min[i] = float(centre[size_t(i)] - half);
      p.box_max[i] = float(centre[size_t(i)] + half);
    }
    const physics::volume_transfer::TransferTable table = transfer_table(c.param(t_.transfer), c.param(t_.color), c.param(t_.opacity));
    p.march = {int32_t(c.param(t_.steps)), int32_t(c.param(t_.bisections)), table.count, c.variant().shader_code};
    p.surface = {float(c.param(t_.iso)), float(c.param(t_.opacity_length)), 0, 0};
    for (int i = 0; i < VOLUME_TRANSFER_MAX_KNOTS; ++i) {
      p.knot_density[i] = gpu_vec4(table.density[size_t(i)]);
      p.knot_rgba[i] = gpu_vec4(table.rgba[size_t(i)]);
    }
    if (const int sun = scene.sun_light(); sun >= 0) {
      const Light& light = scene.lights[size_t(sun)];
      const double n = std::sqrt(light.direction[0] * light.direction[0] + light.direction[1] * light.direction[1] +
                                 light.direction[2] * light.direction[2]);
      for (int i = 0; i < 3; ++i) {
        p.light_direction[i] = float(-light.direction[size_t(i)] / n);
        p.light_irradiance[i] = float(light.irradiance[size_t(i)]);
      }
      p.light_direction[3] = 1;
    }
    return p;
  }

  const VolumeVisualizeTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VolumeVisualizeTable, VolumeVisualizeExecution);

}  // namespace volgraph
