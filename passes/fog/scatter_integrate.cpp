// scatter_integrate: front-to-back integration of froxel_scatter's in-scattering along
// each froxel column into the radiance scattered toward the camera and the
// transmittance, from the camera to the far edge of every slice. Variants: Wronski's
// step (eq. 14.15) and Hillaire's energy-conserving one (eq. 14.16, exact for a
// homogeneous slice and stable as σt → 0). Shader: shaders/scatter_integrate.comp;
// the steps: shaders/include/media.glsl ↔ physics/media.h.
#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "shaders/include/integration_codes.h"
#include "shaders/bindings/scatter_integrate.comp.h"

namespace volgraph {
namespace {

namespace scatter_integrate_shader = shaders::scatter_integrate_comp;

struct ScatterIntegrateTable : PassTable {
  ScatterIntegrateTable()
      : PassTable("scatter_integrate", PassKind::compute,
                  "Front-to-back integration of in-scattering and transmittance along each froxel column.") {
    decl.needs = feature_bit(SceneFeature::medium);
  }
  // Variants: the step (the first is the default).
  VariantHandle hillaire = variant("hillaire", "energy-conserving step: S·(1 − e^(−σt·dz))/σt per slice (Hillaire 2015, eq. 14.16)",
                                   INTEGRATE_HILLAIRE);
  VariantHandle wronski = variant("wronski", "S·dz per slice, then the slice's extinction (Wronski 2014, eq. 14.15)", INTEGRATE_WRONSKI);
  // Slots.
  SlotHandle in_scatter = input("in_scatter", ResourceKind::texture3d, Usage::sampled, "from froxel_scatter");
  SlotHandle media_scattering = input("media_scattering", ResourceKind::texture3d, Usage::sampled, "σs, for σt");
  SlotHandle media_absorption = input("media_absorption", ResourceKind::texture3d, Usage::sampled, "σa, for σt");
  SlotHandle frame = input("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block");
  SlotHandle integrated_scattering = output_like("integrated_scattering", in_scatter, Usage::storage_write,
                                                 "radiance scattered toward the camera, camera to slice");
  SlotHandle integrated_transmittance = output_like("integrated_transmittance", in_scatter, Usage::storage_write,
                                                    "transmittance, camera to slice, rgb");
};

class ScatterIntegrateExecution final : public PassExecution {
 public:
  explicit ScatterIntegrateExecution(const ScatterIntegrateTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "scatter_integrate.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(program_, 0, 0, s.name() + " frame");  // froxel_voxelize's
    const gpu::IntegrateParams params{{s.variant().shader_code, 0, 0, 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, scatter_integrate_shader::params, s.name() + " params", params);
  }

  void record(PassContext& c) override {
    // in_scatter may be a history pair's (froxel_temporal): the cache keeps a group for each object.
    const rhi::BindGroupId group = c.bind_group(
        program_,
        {bind(scatter_integrate_shader::frame, c.buffer(t_.frame)), bind(scatter_integrate_shader::in_scatter, c.view(t_.in_scatter)),
         bind(scatter_integrate_shader::media_scattering, c.view(t_.media_scattering)), bind(scatter_integrate_shader::media_absorption, c.view(t_.media_absorption)),
         bind(scatter_integrate_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(scatter_integrate_shader::integrated_scattering, c.view(t_.integrated_scattering)),
         bind(scatter_integrate_shader::integrated_transmittance, c.view(t_.integrated_transmittance)), bind(scatter_integrate_shader::params, params_)});
    Extent columns = c.extent(t_.in_scatter);
    columns.depth = 1;  // an invocation walks its column front to back
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, columns);
  }

 private:
  const ScatterIntegrateTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(ScatterIntegrateTable, ScatterIntegrateExecution);

}  // namespace volgraph
