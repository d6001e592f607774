// Composite: exposure and tone mapping of linear radiance into the frame's output.
// Variants: none (linear, for .pfm/.exr and exact tests), ACES (Narkowicz 2015 fit),
// Reinhard (Reinhard et al. 2002, eq. 3).
#include "passes/passes.h"

namespace volgraph {

PassDecl composite_pass() {
  PassDecl d;
  d.name = "composite";
  d.kind = PassKind::compute;
  d.doc = "Applies exposure and a tone map to linear radiance; writes the frame's output.";
  d.variants = {
      {"none", "linear radiance × 2^exposure, no tone map"},
      {"aces", "ACES filmic curve (Narkowicz's fit)"},
      {"reinhard", "x / (1 + x) per channel"},
  };
  d.params = {
      param_number("exposure", 0, -20, 20, "EV", "scale by 2^exposure before the tone map"),
  };
  SlotDecl out = slot_out("output", ResourceKind::texture2d, Usage::storage_write, Format::rgba32_float,
                          SizeSpec::of_output(), "the frame: linear or tone-mapped, before sRGB encoding");
  out.format_overridable = true;
  d.slots = {
      slot_in("color", ResourceKind::texture2d, Usage::sampled, "linear radiance"),
      out,
  };
  return d;
}

}  // namespace volgraph
