// cube_mips: a cube map with a mip chain the graph schedules, for rough surfaces that
// reflect or refract it (RTR4 10.5.1: mip-mapped environment maps as a crude prefilter;
// translucency reads the level whose texels span its lobe, environment_lod). Level 0 the
// input cube toward each texel's centre (bilinear: the output's `size` may differ from the
// input's), level k the box mean of level k − 1 per face (faces apart: no seam blending),
// each level a step of its own so the compiler plans each level's barrier, as generate_mips.
// Shaders: shaders/cube_mips_level0.comp, shaders/cube_mips.comp.
#include <array>
#include <string>

#include "graph/execute/pass_execution.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "shaders/bindings/cube_mips.comp.h"
#include "shaders/bindings/cube_mips_level0.comp.h"

namespace volgraph {
namespace {

namespace cube_mips_shader = shaders::cube_mips_comp;
namespace cube_mips_level0_shader = shaders::cube_mips_level0_comp;

constexpr size_t kMaxCubeMipLevels = 12;  // a 2048-texel face's full chain

struct CubeMipsTable : PassTable {
  CubeMipsTable() : PassTable("cube_mips", PassKind::compute, "A cube map and its mip chain: each level the box mean of the one above, face by face.") {}
  // Variants.
  VariantHandle box = variant("box", "each texel the mean of the texels of its face's level above it covers (2 × 2; 3 wide at an odd side's end)");
  // Parameters.
  ParamHandle<int64_t> size = integer("size", 128, 1, 2048, "texels", "level 0's face side (the input cube resampled toward each texel's centre)");
  ParamHandle<int64_t> levels = integer("levels", 8, 1, int64_t(kMaxCubeMipLevels), "", "the chain's levels, level 0 the input (no more than the face's full chain)");
  // Slots.
  SlotHandle cube = input("cube", ResourceKind::texture_cube, Usage::sampled, "the cube (sky_cube.cube, scene_probe.cube)");
  SlotHandle mips = output("mips", ResourceKind::texture_cube, Usage::storage_write, Format::rgba16_float, SizeSpec::square_of(size).with_mips(levels),
                           "the cube and its mip chain");
  // Steps: level 0 resampled, then level k from level k − 1 while k < levels.
  StepHandle level0 = step("level_0", PassKind::compute, {{cube, Usage::sampled}, {mips, Usage::storage_write}});
  std::array<StepHandle, kMaxCubeMipLevels - 1> reductions = reduction_steps();

 private:
  std::array<StepHandle, kMaxCubeMipLevels - 1> reduction_steps() {
    std::array<StepHandle, kMaxCubeMipLevels - 1> steps;
    for (size_t k = 1; k < kMaxCubeMipLevels; ++k) {
      steps[k - 1] = step("level_" + std::to_string(k), PassKind::compute, {{mips, Usage::storage_read_write}}, only_in_while(box, levels, int64_t(k)));
    }
    return steps;
  }
};

class CubeMipsExecution final : public PassExecution {
 public:
  explicit CubeMipsExecution(const CubeMipsTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    resample_ = plumbing::create_compute_program(s.device, "cube_mips_level0.comp");
    reduce_ = plumbing::create_compute_program(s.device, "cube_mips.comp");
  }

  void record(PassContext& c) override {
    const Extent e = c.extent(t_.mips);
    const uint32_t faces = array_layers(ResourceKind::texture_cube);
    if (c.step_is(t_.level0)) {
      namespace shader = cube_mips_level0_shader;
      const rhi::BindGroupId group = c.bind_group(resample_, {bind(shader::cube, c.view(t_.cube)), bind(shader::linear, c.sampler(rhi::StockSampler::linear_clamp)),
                                                              bind(shader::level, c.view(t_.mips, 0))});
      plumbing::dispatch(c.encoder, c.name(), resample_, {group}, {e.width, e.height, faces});
      return;
    }
    const uint32_t level = reduction_level(c);
    if (level == 0 || level >= c.desc(t_.mips).mip_levels) return;  // past the face's chain
    namespace shader = cube_mips_shader;
    const rhi::BindGroupId group = c.bind_group(reduce_, {bind(shader::above, c.view(t_.mips, level - 1)), bind(shader::level, c.view(t_.mips, level))});
    plumbing::dispatch(c.encoder, c.name(), reduce_, {group}, {std::max(1u, e.width >> level), std::max(1u, e.height >> level), faces});
  }

 private:
  // The level the recording step writes (1 … kMaxCubeMipLevels − 1).
  uint32_t reduction_level(const PassContext& c) const {
    for (size_t k = 0; k < t_.reductions.size(); ++k) {
      if (c.step_is(t_.reductions[k])) return uint32_t(k + 1);
    }
    return 0;
  }

  const CubeMipsTable& t_;
  plumbing::ComputeProgram resample_, reduce_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CubeMipsTable, CubeMipsExecution);

}  // namespace volgraph
