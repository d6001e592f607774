// Composite: exposure and tone mapping of linear radiance into the frame's output.
// Variants: none (linear, for .pfm/.exr and exact tests), ACES (Narkowicz 2015 fit),
// Reinhard (Reinhard et al. 2002, eq. 3). Shader: shaders/composite.comp.
#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "physics/tonemap.h"
#include "shaders/bindings/composite.comp.h"
#include "shaders/include/tonemap_codes.h"

namespace volgraph {
namespace {

namespace composite_shader = shaders::composite_comp;

// The shader's codes are the CPU twin's (physics/tonemap.h).
static_assert(int(physics::ToneMap::none) == TONE_MAP_NONE && int(physics::ToneMap::aces) == TONE_MAP_ACES &&
              int(physics::ToneMap::reinhard) == TONE_MAP_REINHARD);

struct CompositeTable : PassTable {
  CompositeTable()
      : PassTable("composite", PassKind::compute, "Applies exposure and a tone map to linear radiance; writes the frame's output.") {}
  // Variants: the tone map (the first is the default).
  VariantHandle none = variant("none", "linear radiance × 2^exposure, no tone map", TONE_MAP_NONE);
  VariantHandle aces = variant("aces", "ACES filmic curve (Narkowicz's fit)", TONE_MAP_ACES);
  VariantHandle reinhard = variant("reinhard", "x / (1 + x) per channel", TONE_MAP_REINHARD);
  // Parameters.
  ParamHandle<double> exposure = number("exposure", 0, -20, 20, "EV", "scale by 2^exposure before the tone map");
  // Slots.
  SlotHandle color = input("color", ResourceKind::texture2d, Usage::sampled, "linear radiance");
  SlotHandle output_slot = output("output", ResourceKind::texture2d, Usage::storage_write, Format::rgba32_float,
                                  SizeSpec::of_output(), "the frame: linear or tone-mapped, before sRGB encoding");
};

class CompositeExecution final : public PassExecution {
 public:
  explicit CompositeExecution(const CompositeTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "composite.comp");
    const Extent size = s.extent(t_.output_slot);
    const gpu::CompositeParams params{{size.width, size.height}, float(s.param(t_.exposure)), s.variant().shader_code};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, composite_shader::params, s.name() + " params", params);
  }

  void record(PassContext& c) override {
    namespace shader = composite_shader;
    const rhi::BindGroupId group =
        c.bind_group(program_, {bind(shader::color, c.view(t_.color)), bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                                bind(shader::frame, c.view(t_.output_slot)), bind(shader::params, params_)});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.output_slot));
  }

 private:
  const CompositeTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CompositeTable, CompositeExecution);

}  // namespace volgraph
