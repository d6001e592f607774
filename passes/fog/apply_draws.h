// The last step every fog technique shares: onto the scene's colour, L = T·L_surface +
// L_scat, as two full-screen draws — the first multiplies the colour by T per channel
// (blend dst × src), the second adds L_scat (blend src + dst). Each draw's fragment
// shader computes its term; both use bind group 0 of the first's layout.
#pragma once

#include <array>

#include "graph/execute/pass_execution.h"
#include "passes/plumbing/programs.h"

namespace volgraph::fog {

class ApplyDraws {
 public:
  // At setup: pipelines for the format of the pass's slot `color` (the inout the draws
  // render onto); shaders by name in shaders/.
  void prepare(const PassSetup& s, SlotHandle color, const char* transmittance_fragment, const char* scattering_fragment);
  bool prepared() const { return bool(attenuate_.pipeline); }
  // The program whose layouts both draws use: bind groups by the first shader's variables.
  const plumbing::RenderProgram& program() const { return attenuate_; }
  // Both draws' programs (to check the uniform blocks the group holds against each).
  std::array<const plumbing::RenderProgram*, 2> programs() const { return {&attenuate_, &add_}; }
  // One render pass onto `color` (loaded), both draws with `group` at set 0.
  void record(PassContext& c, rhi::BindGroupId group) const;

 private:
  SlotHandle color_;
  plumbing::RenderProgram attenuate_, add_;
};

}  // namespace volgraph::fog
