#include "passes/fog/apply_draws.h"

#include <string>

namespace volgraph::fog {
namespace {

plumbing::RenderProgram program(const PassSetup& s, SlotHandle color, rhi::BlendMode blend, const char* fragment) {
  rhi::RenderPipelineDesc pd;
  pd.label = s.name() + " " + fragment;
  pd.colors = {{s.desc(color).format, blend}};
  return plumbing::create_render_program(s.device, pd, "fullscreen.vert", fragment);
}

}  // namespace

void ApplyDraws::prepare(const PassSetup& s, SlotHandle color, const char* transmittance_fragment, const char* scattering_fragment) {
  color_ = color;
  attenuate_ = fog::program(s, color, rhi::BlendMode::multiply, transmittance_fragment);
  add_ = fog::program(s, color, rhi::BlendMode::additive, scattering_fragment);
}

void ApplyDraws::record(PassContext& c, rhi::BindGroupId group) const {
  rhi::RenderPassDesc pass;
  pass.label = c.name();
  pass.colors = {{c.view(color_), rhi::LoadOp::load}};
  c.encoder.begin_render_pass(pass);
  for (const plumbing::RenderProgram* p : {&attenuate_, &add_}) {
    c.encoder.set_pipeline(p->pipeline);
    c.encoder.set_bind_group(0, group);
    c.encoder.draw(3);
  }
  c.encoder.end_render_pass();
}

}  // namespace volgraph::fog
