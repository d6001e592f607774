// Utility passes: clear a texture to a value, copy one texture into a new one.
#include "graph/execute/pass_execution.h"
#include "passes/passes.h"

namespace volgraph {
namespace {

// A render pass that only clears its target.
class ClearExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    const auto value = std::get<std::array<double, 3>>(c.param("value"));
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name;
    pass.colors = {{c.view("target"), rhi::LoadOp::clear, {float(value[0]), float(value[1]), float(value[2]), 1.0f}}};
    c.encoder.begin_render_pass(pass);
    c.encoder.end_render_pass();
  }
};

class CopyExecution final : public PassExecution {
 public:
  void record(PassContext& c) override { c.encoder.copy_texture_to_texture(c.texture("source"), c.texture("copy")); }
};

}  // namespace

PassDecl clear_pass() {
  PassDecl d;
  d.name = "clear";
  d.kind = PassKind::graphics;
  d.doc = "A new texture filled with one value.";
  d.variants = {{"value", "every texel set to `value` (alpha 1)"}};
  d.params = {param_vec3("value", {0, 0, 0}, -1e9, 1e9, "", "the texel value (RGB)")};
  SlotDecl target = slot_out("target", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float,
                             SizeSpec::of_output(), "the cleared texture");
  target.format_overridable = true;
  target.size_overridable = true;
  d.slots = {target};
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new ClearExecution()); };
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
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new CopyExecution()); };
  return d;
}

}  // namespace volgraph
