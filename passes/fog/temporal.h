// What the temporal accumulation passes (froxel_temporal, pixel_temporal) share: their
// parameters (a table the passes' tables derive from), their Params block
// (shaders/include/temporal_blend.glsl's weight, the last frame's view to reproject by)
// and their execution — each frame the Params with the camera remembered from the last
// frame, the bind group of this frame's objects from the device's cache (the history
// pairs' objects swap every frame: the cache holds a group for each), one dispatch over
// the output.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/pass_decl.h"
#include "passes/fog/fog_frame.h"
#include "shaders/include/temporal_params.h"
#include "passes/plumbing/programs.h"

namespace volgraph::fog {

// The passes' shared parameters, alpha (the weight of a new frame once the history is
// long) and reproject; a pass's table derives from it and adds its variants and slots.
struct TemporalTable : PassTable {
  TemporalTable(std::string name, std::string doc) : PassTable(std::move(name), PassKind::compute, std::move(doc)) {
    decl.needs = feature_bit(SceneFeature::medium);
  }
  ParamHandle<double> alpha =
      number("alpha", 0.1, 1e-3, 1, "",
             "weight of a new frame in the moving average once the history holds 1/alpha frames (earlier frames are "
             "averaged equally); 1: no accumulation");
  ParamHandle<bool> reproject =
      flag("reproject", true, "read the history where the last frame's camera saw the point; off: at the same texel");
};

class TemporalExecution : public PassExecution {
 public:
  // `shader` in shaders/, dispatched one invocation per texel of output slot `output`;
  // its Params block at set 0, binding `params_binding` (its frame block at binding 0).
  TemporalExecution(const TemporalTable& table, std::string shader, SlotHandle output, uint32_t params_binding)
      : table_(table), shader_(std::move(shader)), output_(output), params_binding_(params_binding) {}
  void setup(PassSetup& s) final;
  void record(PassContext& c) final;

 protected:
  // The bind group's entries for this frame's objects (params() the Params block).
  virtual std::vector<rhi::BoundResource> entries(PassContext& c) = 0;
  // Blocks besides the Params: made at setup, written every frame (before entries).
  virtual void setup_blocks(PassSetup&) {}
  virtual void write_blocks(PassContext&) {}
  rhi::BufferId params() const { return params_; }

 private:
  gpu::TemporalParams frame_params(const PassContext& c);

  const TemporalTable& table_;
  std::string shader_;
  SlotHandle output_;
  uint32_t params_binding_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
  std::optional<gpu::ViewRays> last_view_;  // the camera the history was made with
};

}  // namespace volgraph::fog
