// froxel_temporal (Hillaire 2015, p. 9): temporal accumulation of froxel_scatter's
// in-scattering volume. With froxel_voxelize's jitter moving each froxel's sample from
// frame to frame, blending the frames averages the froxel's whole footprint: per froxel,
// its centre reprojected into the last frame's grid by the last frame's camera, the last
// frame's result read there trilinearly and blended with this frame's value — a moving
// average whose first frames count equally (shaders/include/temporal_blend.glsl). The
// result (`accumulated`) goes to scatter_integrate and is kept as the next frame's
// history (a history pair: two volumes swapped every frame). On the first frame it is
// this frame's value, unchanged. Shader: shaders/froxel_temporal.comp; reprojection:
// shaders/include/froxel.glsl `froxel_uvw` ↔ physics/froxel.h.
#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"
#include "passes/fog/temporal.h"
#include "shaders/bindings/froxel_temporal.comp.h"

namespace volgraph {
namespace {

namespace froxel_temporal_shader = shaders::froxel_temporal_comp;

struct FroxelTemporalTable : fog::TemporalTable {
  FroxelTemporalTable()
      : TemporalTable("froxel_temporal",
                      "Temporal accumulation of the froxel in-scattering volume: reprojected history blended with this frame's (jittered) volume.") {}
  VariantHandle reprojected =
      variant("reprojected", "the last frame's result read trilinearly where the last frame's camera saw each froxel's centre");
  // Slots (the parameters are TemporalTable's).
  SlotHandle in_scatter = input("in_scatter", ResourceKind::texture3d, Usage::sampled, "this frame's in-scattering, from froxel_scatter");
  SlotHandle frame = input("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block");
  SlotHandle accumulated = output_like("accumulated", in_scatter, Usage::storage_write,
                                       "in-scattering blended over frames, rgb; a: the frames it averages");
  SlotHandle history = TemporalTable::history("history", accumulated, "the last frame's accumulated volume");
};

class FroxelTemporalExecution final : public fog::TemporalExecution {
 public:
  explicit FroxelTemporalExecution(const FroxelTemporalTable& table)
      : TemporalExecution(table, "froxel_temporal.comp", table.accumulated, froxel_temporal_shader::params.binding), t_(table) {}

 private:
  std::vector<rhi::BoundResource> entries(PassContext& c) override {
    return {bind(froxel_temporal_shader::frame, c.buffer(t_.frame)),
            bind(froxel_temporal_shader::in_scatter, c.view(t_.in_scatter)),
            bind(froxel_temporal_shader::history, c.view(t_.history)),
            bind(froxel_temporal_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
            bind(froxel_temporal_shader::trilinear, c.sampler(rhi::StockSampler::linear_clamp)),
            bind(froxel_temporal_shader::accumulated, c.view(t_.accumulated)),
            bind(froxel_temporal_shader::params, params())};
  }

  const FroxelTemporalTable& t_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(FroxelTemporalTable, FroxelTemporalExecution);

}  // namespace volgraph
