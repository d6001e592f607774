#include "passes/fog/apply_draws.h"

#include <string>

namespace volgraph::fog {
namespace {

shading::RenderProgram program(PassContext& c, rhi::BlendMode blend, const char* fragment) {
  rhi::RenderPipelineDesc pd;
  pd.label = c.graph_pass().name + " " + fragment;
  pd.colors = {{c.desc("color").format, blend}};
  return shading::create_render_program(c.device, pd, "fullscreen.vert", fragment);
}

}  // namespace

void ApplyDraws::prepare(PassContext& c, const char* transmittance_fragment, const char* scattering_fragment) {
  attenuate_ = program(c, rhi::BlendMode::multiply, transmittance_fragment);
  add_ = program(c, rhi::BlendMode::additive, scattering_fragment);
}

void ApplyDraws::record(PassContext& c, rhi::BindGroupId group) const {
  rhi::RenderPassDesc pass;
  pass.label = c.graph_pass().name;
  pass.colors = {{c.view("color"), rhi::LoadOp::load}};
  c.encoder.begin_render_pass(pass);
  for (const shading::RenderProgram* p : {&attenuate_, &add_}) {
    c.encoder.set_pipeline(p->pipeline);
    c.encoder.set_bind_group(0, group);
    c.encoder.draw(3);
  }
  c.encoder.end_render_pass();
}

}  // namespace volgraph::fog
