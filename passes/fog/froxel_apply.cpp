// froxel_apply: the froxel chain's result on every pixel, L = T·L_surface + L_scat, with
// T and L_scat read trilinearly from scatter_integrate's volumes at the pixel's depth
// (shaders/include/froxel_lookup.glsl). Two full-screen draws onto the scene's colour:
// the first multiplies it by T (per channel), the second adds L_scat. When the scene has
// no medium the pass is culled and the colour passes through unchanged.
#include "graph/execute/pass_execution.h"
#include "passes/fog/fog_passes.h"
#include "passes/fog/apply_draws.h"

namespace volgraph {
namespace {

class FroxelApplyExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!draws_.prepared()) prepare(c);
    draws_.record(c, group_);
  }

 private:
  void prepare(PassContext& c) {
    using namespace rhi;
    draws_.prepare(c, "froxel_apply_transmittance.frag", "froxel_apply_scattering.frag");
    SamplerDesc trilinear{"trilinear"};
    trilinear.filter = trilinear.mip_filter = Filter::linear;
    group_ = c.device.create_bind_group(
        {"froxel_apply", draws_.layout(),
         {BindGroupEntry::of(0, c.buffer("frame")), BindGroupEntry::of(1, c.view("depth")),
          BindGroupEntry::of(2, c.view("integrated_scattering")), BindGroupEntry::of(3, c.view("integrated_transmittance")),
          BindGroupEntry::of(4, c.device.create_sampler(trilinear)), BindGroupEntry::of(5, c.device.create_sampler({"nearest"}))}});
  }

  fog::ApplyDraws draws_;
  rhi::BindGroupId group_;
};

}  // namespace

PassDecl froxel_apply_pass() {
  PassDecl d;
  d.name = "froxel_apply";
  d.kind = PassKind::graphics;
  d.doc = "Applies the integrated froxel volumes to the scene's colour: L = T·L_surface + L_scat at each pixel's depth.";
  d.variants = {{"trilinear", "one trilinear lookup per pixel at its view depth"}};
  d.slots = {
      slot_inout("color", ResourceKind::texture2d, Usage::color_attachment_load, "the scene's linear radiance"),
      slot_in("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth"),
      slot_in("integrated_scattering", ResourceKind::texture3d, Usage::sampled, "from scatter_integrate"),
      slot_in("integrated_transmittance", ResourceKind::texture3d, Usage::sampled, "from scatter_integrate"),
      slot_in("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block"),
  };
  d.slots[1].format = Format::d32_float;
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new FroxelApplyExecution()); };
  return d;
}

}  // namespace volgraph
