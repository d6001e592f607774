#include "passes/fog/temporal.h"

#include "graph/scene/scene.h"

namespace volgraph::fog {

void TemporalExecution::setup(PassSetup& s) {
  program_ = plumbing::create_compute_program(s.device, shader_);
  // The Params are written every frame, the frame block by froxel_voxelize or the pass: checked once.
  plumbing::check_wrapped_uniform_mirror<gpu::TemporalParams>(program_, 0, params_binding_, s.name() + " params");
  plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(program_, 0, 0, s.name() + " frame");
  params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::TemporalParams),
                                    rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  setup_blocks(s);
}

void TemporalExecution::record(PassContext& c) {
  write_blocks(c);
  const gpu::TemporalParams params = frame_params(c);
  c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
  const rhi::BindGroupId group = c.bind_group(program_, entries(c));
  plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(output_));
}

// The last frame's camera is the view the history was made with (the executor lets the
// scene's camera change between frames); the first frame has none.
gpu::TemporalParams TemporalExecution::frame_params(const PassContext& c) {
  const gpu::ViewRays view = pack_view_rays(c.scene->camera, c.frame_size());
  gpu::TemporalParams p{};
  p.previous_view = last_view_.value_or(view);
  p.blend[0] = float(c.param(table_.alpha));
  p.blend[1] = c.history_valid && last_view_ ? 1.0f : 0.0f;
  p.blend[2] = c.param(table_.reproject) ? 1.0f : 0.0f;
  last_view_ = view;
  return p;
}

}  // namespace volgraph::fog
