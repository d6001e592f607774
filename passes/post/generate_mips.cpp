// generate_mips: a mip chain of an image the graph schedules (RTR4 6.2.2): level 0 the
// input's texels, level k the box mean of level k − 1's texels it covers (2 × 2, or 3 wide
// along an odd side's last texel, so that every texel of level k − 1 counts), each level
// a step of its own — one graph pass, so the compiler plans the barrier between a level's
// write and the next level's read like any other. `levels` (clamped to the frame's full
// chain: SizeSpec::with_mips) sets the chain's length; steps past it do not run.
// Readers sample the whole chain at a level of detail (translucency's roughness blur).
// Shaders: shaders/generate_mips_level0.comp, shaders/generate_mips.comp.
#include <array>
#include <string>

#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "shaders/bindings/generate_mips.comp.h"
#include "shaders/bindings/generate_mips_level0.comp.h"

namespace volgraph {
namespace {

namespace generate_mips_shader = shaders::generate_mips_comp;
namespace generate_mips_level0_shader = shaders::generate_mips_level0_comp;

constexpr size_t kMaxMipLevels = 14;  // a 8192-texel side's full chain

struct GenerateMipsTable : PassTable {
  GenerateMipsTable() : PassTable("generate_mips", PassKind::compute, "A mip chain of an image: each level the box mean of the one above.") {}
  // Variants.
  VariantHandle box = variant("box", "each texel the mean of the texels of the level above it covers (2 × 2; 3 wide at an odd side's end)");
  // Parameters.
  ParamHandle<int64_t> levels = integer("levels", 8, 1, int64_t(kMaxMipLevels), "",
                                        "the chain's levels, level 0 the input (no more than the frame's full chain)");
  // Slots.
  SlotHandle color = input("color", ResourceKind::texture2d, Usage::sampled, "the image (level 0)", {.format = Format::rgba16_float});
  SlotHandle mips = output("mips", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output().with_mips(levels),
                           "the image and its mip chain");
  // Steps: level 0 copied, then level k from level k − 1 while k < levels.
  StepHandle level0 = step("level_0", PassKind::compute, {{color, Usage::sampled}, {mips, Usage::storage_write}});
  std::array<StepHandle, kMaxMipLevels - 1> reductions = reduction_steps();

 private:
  std::array<StepHandle, kMaxMipLevels - 1> reduction_steps() {
    std::array<StepHandle, kMaxMipLevels - 1> steps;
    for (size_t k = 1; k < kMaxMipLevels; ++k) {
      steps[k - 1] = step("level_" + std::to_string(k), PassKind::compute, {{mips, Usage::storage_read_write}},
                          only_in_while(box, levels, int64_t(k)));
    }
    return steps;
  }
};

class GenerateMipsExecution final : public PassExecution {
 public:
  explicit GenerateMipsExecution(const GenerateMipsTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    copy_ = plumbing::create_compute_program(s.device, "generate_mips_level0.comp");
    reduce_ = plumbing::create_compute_program(s.device, "generate_mips.comp");
  }

  void record(PassContext& c) override {
    if (c.step_is(t_.level0)) return record_level0(c);
    const uint32_t level = reduction_level(c);
    if (level >= c.desc(t_.mips).mip_levels) return;  // a frame too small for this level
    namespace shader = generate_mips_shader;
    const rhi::BindGroupId group =
        c.bind_group(reduce_, {bind(shader::above, c.view(t_.mips, level - 1)), bind(shader::level, c.view(t_.mips, level))});
    const Extent e = c.extent(t_.mips);
    plumbing::dispatch(c.encoder, c.name(), reduce_, {group}, {std::max(1u, e.width >> level), std::max(1u, e.height >> level), 1});
  }

 private:
  void record_level0(PassContext& c) {
    namespace shader = generate_mips_level0_shader;
    const rhi::BindGroupId group = c.bind_group(copy_, {bind(shader::color, c.view(t_.color)), bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                                                         bind(shader::level, c.view(t_.mips, 0))});
    plumbing::dispatch(c.encoder, c.name(), copy_, {group}, c.extent(t_.mips));
  }

  // The level the recording step writes (1 … kMaxMipLevels − 1).
  uint32_t reduction_level(const PassContext& c) const {
    for (size_t k = 0; k < t_.reductions.size(); ++k) {
      if (c.step_is(t_.reductions[k])) return uint32_t(k + 1);
    }
    return 0;
  }

  const GenerateMipsTable& t_;
  plumbing::ComputeProgram copy_, reduce_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(GenerateMipsTable, GenerateMipsExecution);

}  // namespace volgraph
