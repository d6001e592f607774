// scatter_integrate: front-to-back integration of froxel_scatter's in-scattering along
// each froxel column into the radiance scattered toward the camera and the
// transmittance, from the camera to the far edge of every slice. Variants: Wronski's
// step (eq. 14.15) and Hillaire's energy-conserving one (eq. 14.16, exact for a
// homogeneous slice and stable as σt → 0). Shader: shaders/scatter_integrate.comp;
// the steps: shaders/include/media.glsl ↔ passes/shading/media.h.
#include <array>

#include "graph/execute/pass_execution.h"
#include "passes/fog/fog_passes.h"
#include "passes/shading/programs.h"

namespace volgraph {
namespace {

class ScatterIntegrateExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    rhi::BindGroupId& group = groups_[c.parity()];  // in_scatter may be a history pair's (froxel_temporal)
    if (!group) group = make_group(c);
    Extent columns = c.desc("in_scatter").extent;
    columns.depth = 1;  // an invocation walks its column front to back
    shading::dispatch(c.encoder, c.graph_pass().name, program_, {group}, columns);
  }

 private:
  void prepare(PassContext& c) {
    using namespace rhi;
    program_ = shading::create_compute_program(c.device, "scatter_integrate.comp");
    const int32_t method[4] = {c.variant() == "wronski" ? 0 : 1, 0, 0, 0};
    params_ = c.device.create_buffer({"scatter_integrate params", sizeof(method), buffer_usage::uniform | buffer_usage::copy_dst});
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(method)));
    nearest_ = c.device.create_sampler({"nearest"});
  }

  rhi::BindGroupId make_group(PassContext& c) {
    using rhi::BindGroupEntry;
    return c.device.create_bind_group(
        {"scatter_integrate", program_.layouts[0],
         {BindGroupEntry::of(0, c.buffer("frame")), BindGroupEntry::of(1, c.view("in_scatter")),
          BindGroupEntry::of(2, c.view("media_scattering")), BindGroupEntry::of(3, c.view("media_absorption")),
          BindGroupEntry::of(4, nearest_), BindGroupEntry::of(5, c.view("integrated_scattering")),
          BindGroupEntry::of(6, c.view("integrated_transmittance")), BindGroupEntry::of(7, params_)}});
  }

  shading::ComputeProgram program_;
  rhi::BufferId params_;
  rhi::SamplerId nearest_;
  std::array<rhi::BindGroupId, 2> groups_;
};

}  // namespace

PassDecl scatter_integrate_pass() {
  PassDecl d;
  d.name = "scatter_integrate";
  d.kind = PassKind::compute;
  d.doc = "Front-to-back integration of in-scattering and transmittance along each froxel column.";
  d.variants = {
      {"hillaire", "energy-conserving step: S·(1 − e^(−σt·dz))/σt per slice (Hillaire 2015, eq. 14.16)"},
      {"wronski", "S·dz per slice, then the slice's extinction (Wronski 2014, eq. 14.15)"},
  };
  d.slots = {
      slot_in("in_scatter", ResourceKind::texture3d, Usage::sampled, "from froxel_scatter"),
      slot_in("media_scattering", ResourceKind::texture3d, Usage::sampled, "σs, for σt"),
      slot_in("media_absorption", ResourceKind::texture3d, Usage::sampled, "σa, for σt"),
      slot_in("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block"),
      slot_out_like("integrated_scattering", "in_scatter", Usage::storage_write, "radiance scattered toward the camera, camera to slice"),
      slot_out_like("integrated_transmittance", "in_scatter", Usage::storage_write, "transmittance, camera to slice, rgb"),
  };
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new ScatterIntegrateExecution()); };
  d.parity_bind_groups = true;
  return d;
}

}  // namespace volgraph
