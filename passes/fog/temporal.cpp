#include "passes/fog/temporal.h"

#include "graph/scene/scene.h"

namespace volgraph::fog {

std::vector<ParamDecl> temporal_params() {
  return {
      param_number("alpha", 0.1, 1e-3, 1, "",
                   "weight of a new frame in the moving average once the history holds 1/alpha frames (earlier frames are "
                   "averaged equally); 1: no accumulation"),
      param_bool("reproject", true, "read the history where the last frame's camera saw the point; off: at the same texel"),
  };
}

void TemporalExecution::record(PassContext& c) {
  if (!program_.pipeline) prepare(c);
  write_blocks(c);
  const GpuTemporalParams params = frame_params(c);
  c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
  rhi::BindGroupId& group = groups_[c.parity()];
  if (!group) group = c.device.create_bind_group({c.graph_pass().name, program_.layouts[0], entries(c)});
  c.encoder.begin_compute_pass(c.graph_pass().name);
  c.encoder.set_pipeline(program_.pipeline);
  c.encoder.set_bind_group(0, group);
  const auto groups = program_.groups_for(c.desc(output_).extent);
  c.encoder.dispatch(groups[0], groups[1], groups[2]);
  c.encoder.end_compute_pass();
}

void TemporalExecution::prepare(PassContext& c) {
  program_ = shading::create_compute_program(c.device, shader_);
  params_ = c.device.create_buffer({c.graph_pass().name + " params", sizeof(GpuTemporalParams),
                                    rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  nearest_ = c.device.create_sampler({"nearest"});
  rhi::SamplerDesc linear{"linear"};
  linear.filter = rhi::Filter::linear;
  linear_ = c.device.create_sampler(linear);
}

// The last frame's camera is the view the history was made with (the executor lets the
// scene's camera change between frames); the first frame has none.
GpuTemporalParams TemporalExecution::frame_params(const PassContext& c) {
  const GpuViewRays view = pack_view_rays(c.scene->camera, c.graph.output_size);
  GpuTemporalParams p{};
  p.previous_view = last_view_.value_or(view);
  p.blend[0] = float(std::get<double>(c.param("alpha")));
  p.blend[1] = c.history_valid && last_view_ ? 1.0f : 0.0f;
  p.blend[2] = std::get<bool>(c.param("reproject")) ? 1.0f : 0.0f;
  last_view_ = view;
  return p;
}

}  // namespace volgraph::fog
