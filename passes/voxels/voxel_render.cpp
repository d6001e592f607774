// voxel_render: voxelize's grid drawn over the scene (RTR4 13.10). Variant `dda`: direct ray
// casting of the grid — per pixel, the camera ray against the grid's box (slab method), then
// Amanatides & Woo 1987's DDA, voxel to voxel, to the first set voxel; flat Lambert shading by
// the normal of the face the ray entered it through, lit by the scene's first directional
// light (else a headlight of irradiance π), albedo `albedo`. The voxels are depth-tested against
// the scene's depth; where the ray misses them the scene's colour shows. Outputs `color` and
// `hit` (r the distance in metres along the ray to the entered face, 0 where none). A compute
// pass writing a new image, as volume_visualize. Shader: shaders/voxel_render.comp.
#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/sun_for_shader.h"
#include "passes/register_pass.h"
#include "shaders/bindings/voxel_render.comp.h"
#include "shaders/include/voxel_grid.h"

namespace volgraph {
namespace {

namespace voxel_render_shader = shaders::voxel_render_comp;

struct VoxelRenderTable : PassTable {
  VoxelRenderTable()
      : PassTable("voxel_render", PassKind::compute, "voxelize's grid drawn over the scene: ray cast by a 3D DDA (Amanatides & Woo 1987).") {}
  // Variants.
  VariantHandle dda = variant("dda", "per pixel, Amanatides & Woo's DDA through the grid to the first set voxel, shaded by its entered face");
  // Parameters.
  ParamHandle<std::array<double, 3>> albedo = vec3("albedo", {0.8, 0.8, 0.8}, 0, 1, "", "the voxels' Lambertian albedo");
  // Slots.
  SlotHandle voxels = input("voxels", ResourceKind::texture3d, Usage::sampled, "voxelize.voxels: r 1 where set");
  SlotHandle grid = input("grid", ResourceKind::buffer, Usage::uniform_read, "voxelize.grid: the grid's placement");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth: the voxels are tested against it",
                           {.format = Format::d32_float});
  SlotHandle scene_color = input("scene_color", ResourceKind::texture2d, Usage::sampled, "the scene's linear radiance, where the rays miss");
  SlotHandle color = output_like("color", scene_color, Usage::storage_write, "the voxels over the scene");
  SlotHandle hit = output("hit", ResourceKind::texture2d, Usage::storage_write, Format::r32_float, SizeSpec::of_output(),
                          "r the distance (m) along the pixel's ray to the voxel face it enters, 0 where it meets none");
};

class VoxelRenderExecution final : public PassExecution {
 public:
  explicit VoxelRenderExecution(const VoxelRenderTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "voxel_render.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::VoxelRenderParams>(program_, voxel_render_shader::params, s.name() + " params");
    plumbing::check_wrapped_uniform_mirror<gpu::VoxelGrid>(program_, voxel_render_shader::grid, s.name() + " grid");
    params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::VoxelRenderParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    namespace shader = voxel_render_shader;
    const gpu::VoxelRenderParams params = render_params(c);
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::params, params_), bind(shader::grid, c.buffer(t_.grid)), bind(shader::voxels, c.view(t_.voxels)),
                   bind(shader::scene_depth, c.view(t_.depth)), bind(shader::scene_color, c.view(t_.scene_color)),
                   bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(shader::color, c.view(t_.color)),
                   bind(shader::hit, c.view(t_.hit))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.color));
  }

 private:
  gpu::VoxelRenderParams render_params(const PassContext& c) const {
    const Scene& scene = *c.scene;
    gpu::VoxelRenderParams p{};
    p.view = fog::pack_view_rays(scene.camera, c.extent(t_.color));
    const std::array<double, 3> albedo = c.param(t_.albedo);
    for (int i = 0; i < 3; ++i) p.albedo[i] = float(albedo[size_t(i)]);
    plumbing::write_sun_for_shader(scene, p.light_direction, p.light_irradiance);
    return p;
  }

  const VoxelRenderTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VoxelRenderTable, VoxelRenderExecution);

}  // namespace volgraph
