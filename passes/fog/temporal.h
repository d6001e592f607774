// What the temporal accumulation passes (froxel_temporal, pixel_temporal) share: their
// parameters, their Params block (shaders/include/temporal_blend.glsl's weight, the
// last frame's view to reproject by) and their execution — each frame the Params with
// the camera remembered from the last frame, the bind group of this frame's parity (the
// history pairs' objects swap every frame), one dispatch over the output.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/pass_decl.h"
#include "passes/fog/fog_frame.h"
#include "passes/shading/programs.h"

namespace volgraph::fog {

// std140 mirror of the temporal shaders' Params block.
struct GpuTemporalParams {
  GpuViewRays previous_view;
  float blend[4];  // alpha, history valid (0/1), reproject (0/1), unused
};

// alpha (the weight of a new frame once the history is long) and reproject.
std::vector<ParamDecl> temporal_params();

class TemporalExecution : public PassExecution {
 public:
  // `shader` in shaders/, dispatched one invocation per texel of output slot `output`.
  TemporalExecution(std::string shader, std::string output) : shader_(std::move(shader)), output_(std::move(output)) {}
  void record(PassContext& c) final;

 protected:
  // The bind group's entries for this frame's objects (params(), nearest(), linear()).
  virtual std::vector<rhi::BindGroupEntry> entries(PassContext& c) = 0;
  // Per-frame blocks besides the Params (called before entries on the first frame).
  virtual void write_blocks(PassContext&) {}
  rhi::BufferId params() const { return params_; }
  rhi::SamplerId nearest() const { return nearest_; }
  rhi::SamplerId linear() const { return linear_; }

 private:
  void prepare(PassContext& c);
  GpuTemporalParams frame_params(const PassContext& c);

  std::string shader_, output_;
  shading::ComputeProgram program_;
  rhi::BufferId params_;
  rhi::SamplerId nearest_, linear_;
  std::array<rhi::BindGroupId, 2> groups_;  // per parity
  std::optional<GpuViewRays> last_view_;    // the camera the history was made with
};

}  // namespace volgraph::fog
