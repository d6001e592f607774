// The last step every fog technique shares: onto the scene's colour, L = T·L_surface +
// L_scat, as two full-screen draws — the first multiplies the colour by T per channel
// (blend dst × src), the second adds L_scat (blend src + dst). Each draw's fragment
// shader computes its term; both use bind group 0 of the first's layout.
#pragma once

#include "graph/execute/pass_execution.h"
#include "passes/shading/programs.h"

namespace volgraph::fog {

class ApplyDraws {
 public:
  // Pipelines for `color`'s format; shaders by name in shaders/.
  void prepare(PassContext& c, const char* transmittance_fragment, const char* scattering_fragment);
  bool prepared() const { return bool(attenuate_.pipeline); }
  rhi::BindGroupLayoutId layout() const { return attenuate_.layouts[0]; }
  // One render pass onto `color` (loaded), both draws with `group` at set 0.
  void record(PassContext& c, rhi::BindGroupId group) const;

 private:
  shading::RenderProgram attenuate_, add_;
};

}  // namespace volgraph::fog
