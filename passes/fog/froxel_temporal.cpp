// froxel_temporal (Hillaire 2015, p. 9): temporal accumulation of froxel_scatter's
// in-scattering volume. With froxel_voxelize's jitter moving each froxel's sample from
// frame to frame, blending the frames averages the froxel's whole footprint: per froxel,
// its centre reprojected into the last frame's grid by the last frame's camera, the last
// frame's result read there trilinearly and blended with this frame's value — a moving
// average whose first frames count equally (shaders/include/temporal_blend.glsl). The
// result (`accumulated`) goes to scatter_integrate and is kept as the next frame's
// history (a history pair: two volumes swapped every frame). On the first frame it is
// this frame's value, unchanged. Shader: shaders/froxel_temporal.comp; reprojection:
// shaders/include/froxel.glsl `froxel_uvw` ↔ passes/shading/froxel.h.
#include "graph/execute/pass_execution.h"
#include "passes/fog/fog_passes.h"
#include "passes/fog/temporal.h"

namespace volgraph {
namespace {

class FroxelTemporalExecution final : public fog::TemporalExecution {
 public:
  FroxelTemporalExecution() : TemporalExecution("froxel_temporal.comp", "accumulated") {}

 private:
  std::vector<rhi::BindGroupEntry> entries(PassContext& c) override {
    using rhi::BindGroupEntry;
    return {BindGroupEntry::of(0, c.buffer("frame")), BindGroupEntry::of(1, c.view("in_scatter")),
            BindGroupEntry::of(2, c.view("history")), BindGroupEntry::of(3, nearest()), BindGroupEntry::of(4, linear()),
            BindGroupEntry::of(5, c.view("accumulated")), BindGroupEntry::of(6, params())};
  }
};

}  // namespace

PassDecl froxel_temporal_pass() {
  PassDecl d;
  d.name = "froxel_temporal";
  d.kind = PassKind::compute;
  d.doc = "Temporal accumulation of the froxel in-scattering volume: reprojected history blended with this frame's (jittered) volume.";
  d.variants = {{"reprojected", "the last frame's result read trilinearly where the last frame's camera saw each froxel's centre"}};
  d.params = fog::temporal_params();
  d.slots = {
      slot_in("in_scatter", ResourceKind::texture3d, Usage::sampled, "this frame's in-scattering, from froxel_scatter"),
      slot_in("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block"),
      slot_out_like("accumulated", "in_scatter", Usage::storage_write,
                    "in-scattering blended over frames, rgb; a: the frames it averages"),
      slot_history("history", "accumulated", "the last frame's accumulated volume"),
  };
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new FroxelTemporalExecution()); };
  d.parity_bind_groups = true;
  return d;
}

}  // namespace volgraph
