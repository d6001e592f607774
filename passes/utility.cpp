// Utility passes: clear a texture to a value, copy one texture into a new one.
#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"

namespace volgraph {
namespace {

struct ClearTable : PassTable {
  ClearTable() : PassTable("clear", PassKind::graphics, "A new texture filled with one value.") {}
  // Variants.
  VariantHandle value_variant = variant("value", "every texel set to `value` (alpha 1)");
  // Parameters.
  ParamHandle<std::array<double, 3>> value = vec3("value", {0, 0, 0}, -1e9, 1e9, "", "the texel value (RGB)");
  // Slots.
  SlotHandle target = output("target", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float,
                             SizeSpec::of_output(), "the cleared texture",
                             {.format_overridable = true, .size_overridable = true});
};

// A render pass that only clears its target.
class ClearExecution final : public PassExecution {
 public:
  explicit ClearExecution(const ClearTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    const std::array<double, 3>& v = s.param(t_.value);
    value_ = {float(v[0]), float(v[1]), float(v[2]), 1.0f};
  }

  void record(PassContext& c) override {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.target), rhi::LoadOp::clear, {value_[0], value_[1], value_[2], value_[3]}}};
    c.encoder.begin_render_pass(pass);
    c.encoder.end_render_pass();
  }

 private:
  const ClearTable& t_;
  std::array<float, 4> value_{};
};

struct CopyTable : PassTable {
  CopyTable() : PassTable("copy", PassKind::transfer, "A copy of a texture (same format and size), e.g. the scene colour refraction reads.") {}
  // Variants.
  VariantHandle full = variant("full", "the whole texture");
  // Slots.
  SlotHandle source = input("source", ResourceKind::texture2d, Usage::copy_src, "texture to copy");
  SlotHandle copy = output_like("copy", source, Usage::copy_dst, "the copy");
};

class CopyExecution final : public PassExecution {
 public:
  explicit CopyExecution(const CopyTable& table) : t_(table) {}
  void record(PassContext& c) override { c.encoder.copy_texture_to_texture(c.texture(t_.source), c.texture(t_.copy)); }

 private:
  const CopyTable& t_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(ClearTable, ClearExecution);

VOLGRAPH_REGISTER_PASS(CopyTable, CopyExecution);

}  // namespace volgraph
