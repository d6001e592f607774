// froxel_apply: the froxel chain's result on every pixel, L = T·L_surface + L_scat, with
// T and L_scat read trilinearly from scatter_integrate's volumes at the pixel's depth
// (shaders/include/froxel_lookup.glsl). Two full-screen draws onto the scene's colour:
// the first multiplies it by T (per channel), the second adds L_scat. When the scene has
// no medium the pass is culled and the colour passes through unchanged.
#include "graph/execute/pass_execution.h"
#include "passes/fog/fog_passes.h"
#include "passes/shading/programs.h"

namespace volgraph {
namespace {

class FroxelApplyExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!attenuate_.pipeline) prepare(c);
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name;
    pass.colors = {{c.view("color"), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    for (const shading::RenderProgram* program : {&attenuate_, &add_}) {
      c.encoder.set_pipeline(program->pipeline);
      c.encoder.set_bind_group(0, group_);
      c.encoder.draw(3);
    }
    c.encoder.end_render_pass();
  }

 private:
  shading::RenderProgram program(PassContext& c, rhi::BlendMode blend, const char* fragment) {
    rhi::RenderPipelineDesc pd;
    pd.label = std::string("froxel_apply ") + fragment;
    pd.colors = {{c.desc("color").format, blend}};
    return shading::create_render_program(c.device, pd, "fullscreen.vert", fragment);
  }

  void prepare(PassContext& c) {
    using namespace rhi;
    attenuate_ = program(c, BlendMode::multiply, "froxel_apply_transmittance.frag");
    add_ = program(c, BlendMode::additive, "froxel_apply_scattering.frag");
    SamplerDesc trilinear{"trilinear"};
    trilinear.filter = trilinear.mip_filter = Filter::linear;
    group_ = c.device.create_bind_group(
        {"froxel_apply", attenuate_.layouts[0],
         {BindGroupEntry::of(0, c.buffer("frame")), BindGroupEntry::of(1, c.view("depth")),
          BindGroupEntry::of(2, c.view("integrated_scattering")), BindGroupEntry::of(3, c.view("integrated_transmittance")),
          BindGroupEntry::of(4, c.device.create_sampler(trilinear)), BindGroupEntry::of(5, c.device.create_sampler({"nearest"}))}});
  }

  shading::RenderProgram attenuate_, add_;
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
