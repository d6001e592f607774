// Composite: exposure and tone mapping of linear radiance into the frame's output.
// Variants: none (linear, for .pfm/.exr and exact tests), ACES (Narkowicz 2015 fit),
// Reinhard (Reinhard et al. 2002, eq. 3). Shader: shaders/composite.comp.
#include "graph/execute/pass_execution.h"
#include "passes/passes.h"
#include "passes/shading/programs.h"
#include "passes/shading/tonemap.h"

namespace volgraph {
namespace {

shading::ToneMap tone_map_of(std::string_view variant) {
  if (variant == "aces") return shading::ToneMap::aces;
  if (variant == "reinhard") return shading::ToneMap::reinhard;
  return shading::ToneMap::none;
}

class CompositeExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    const Extent size = c.desc("output").extent;
    struct {
      uint32_t size[2];
      float exposure_ev;
      int32_t tone_map_op;
    } block{{size.width, size.height}, float(std::get<double>(c.param("exposure"))), int32_t(tone_map_of(c.variant()))};
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&block, 1)));
    shading::dispatch(c.encoder, c.graph_pass().name, program_, {group_}, size);
  }

 private:
  // Pipeline and bindings, once: the graph's resources keep their handles for the
  // executor's lifetime.
  void prepare(PassContext& c) {
    using namespace rhi;
    program_ = shading::create_compute_program(c.device, "composite.comp");
    params_ = c.device.create_buffer({"composite params", 16, buffer_usage::uniform | buffer_usage::copy_dst});
    group_ = c.device.create_bind_group({"composite", program_.layouts[0],
                                         {BindGroupEntry::of(0, c.view("color")), BindGroupEntry::of(1, c.device.create_sampler({"nearest"})),
                                          BindGroupEntry::of(2, c.view("output")), BindGroupEntry::of(3, params_)}});
  }

  shading::ComputeProgram program_;
  rhi::BindGroupId group_;
  rhi::BufferId params_;
};

}  // namespace

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
  d.slots = {
      slot_in("color", ResourceKind::texture2d, Usage::sampled, "linear radiance"),
      slot_out("output", ResourceKind::texture2d, Usage::storage_write, Format::rgba32_float, SizeSpec::of_output(),
               "the frame: linear or tone-mapped, before sRGB encoding"),
  };
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new CompositeExecution()); };
  return d;
}

}  // namespace volgraph
