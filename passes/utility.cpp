// Utility passes: clear a texture to a value, copy one texture into a new one.
#include "passes/passes.h"

namespace volgraph {

PassDecl clear_pass() {
  PassDecl d;
  d.name = "clear";
  d.kind = PassKind::transfer;
  d.doc = "A new texture filled with one value.";
  d.variants = {{"value", "every texel set to `value` (alpha 1)"}};
  d.params = {param_vec3("value", {0, 0, 0}, -1e9, 1e9, "", "the texel value (RGB)")};
  SlotDecl target = slot_out("target", ResourceKind::texture2d, Usage::copy_dst, Format::rgba16_float,
                             SizeSpec::of_output(), "the cleared texture");
  target.format_overridable = true;
  target.size_overridable = true;
  d.slots = {target};
  return d;
}

PassDecl copy_pass() {
  PassDecl d;
  d.name = "copy";
  d.kind = PassKind::transfer;
  d.doc = "A copy of a texture (same format and size), e.g. the scene colour refraction reads.";
  d.variants = {{"full", "the whole texture"}};
  d.slots = {
      slot_in("source", ResourceKind::texture2d, Usage::copy_src, "texture to copy"),
      slot_out_like("copy", "source", Usage::copy_dst, "the copy"),
  };
  return d;
}

}  // namespace volgraph
