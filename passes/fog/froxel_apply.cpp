// froxel_apply: the froxel chain's result on every pixel, L = T·L_surface + L_scat, with
// T and L_scat read trilinearly from scatter_integrate's volumes at the pixel's depth
// (shaders/include/froxel_lookup.glsl). Two full-screen draws onto the scene's colour:
// the first multiplies it by T (per channel), the second adds L_scat. When the scene has
// no medium the pass is culled and the colour passes through unchanged.
#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"
#include "passes/fog/apply_draws.h"
#include "passes/fog/fog_frame.h"
#include "shaders/bindings/froxel_apply_transmittance.frag.h"

namespace volgraph {
namespace {

namespace froxel_apply_transmittance_shader = shaders::froxel_apply_transmittance_frag;

struct FroxelApplyTable : PassTable {
  FroxelApplyTable()
      : PassTable("froxel_apply", PassKind::graphics,
                  "Applies the integrated froxel volumes to the scene's colour: L = T·L_surface + L_scat at each pixel's depth.") {
    decl.needs = feature_bit(SceneFeature::medium);
  }
  // Variants.
  VariantHandle trilinear = variant("trilinear", "one trilinear lookup per pixel at its view depth");
  // Slots.
  SlotHandle color = inout("color", ResourceKind::texture2d, Usage::color_attachment_load, "the scene's linear radiance");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth", {.format = Format::d32_float});
  SlotHandle integrated_scattering = input("integrated_scattering", ResourceKind::texture3d, Usage::sampled, "from scatter_integrate");
  SlotHandle integrated_transmittance =
      input("integrated_transmittance", ResourceKind::texture3d, Usage::sampled, "from scatter_integrate");
  SlotHandle frame = input("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block");
};

class FroxelApplyExecution final : public PassExecution {
 public:
  explicit FroxelApplyExecution(const FroxelApplyTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    draws_.prepare(s, t_.color, "froxel_apply_transmittance.frag", "froxel_apply_scattering.frag");
    for (const plumbing::RenderProgram* p : draws_.programs()) {
      plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(*p, 0, 0, s.name() + " frame");  // froxel_voxelize's
    }
  }

  void record(PassContext& c) override {
    const rhi::BindGroupId group = c.bind_group(
        draws_.program(),
        {bind(froxel_apply_transmittance_shader::frame, c.buffer(t_.frame)), bind(froxel_apply_transmittance_shader::scene_depth, c.view(t_.depth)),
         bind(froxel_apply_transmittance_shader::integrated_scattering, c.view(t_.integrated_scattering)), bind(froxel_apply_transmittance_shader::integrated_transmittance, c.view(t_.integrated_transmittance)),
         bind(froxel_apply_transmittance_shader::trilinear, c.sampler(rhi::StockSampler::trilinear_clamp)), bind(froxel_apply_transmittance_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))});
    draws_.record(c, group);
  }

 private:
  const FroxelApplyTable& t_;
  fog::ApplyDraws draws_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(FroxelApplyTable, FroxelApplyExecution);

}  // namespace volgraph
