#include "passes/fog/pixel_fog.h"

#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"

namespace volgraph::fog {

void PixelFogExecution::setup(PassSetup& s) {
  const PixelFogInputs in = inputs_of_(s);
  program_ = plumbing::create_compute_program(s.device, shader_);
  FogFrameInputs frame_inputs;
  frame_inputs.grid = s.extent(t_.fog_scattering);
  frame_inputs.range = {s.scene->camera.near, s.scene->camera.far, physics::FroxelDistribution::linear};
  frame_inputs.ambient_radiance = in.ambient;
  frame_inputs.jitter = false;
  const GpuFogFrame frame = make_fog_frame(s, 0, frame_inputs, lighting_);
  plumbing::check_wrapped_uniform_mirror<GpuFogFrame>(program_, 0, 0, s.name() + " frame");
  frame_ = plumbing::create_uniform_block(s.device, s.name() + " frame", frame);
  if (!in.params.empty()) {
    rhi::check_uniform_block(plumbing::uniform_block_at(program_.uniform_blocks, 0, 5), in.params.size(), in.params_offsets,
                             s.name() + " params");
    params_ = plumbing::create_uniform_buffer(s.device, s.name() + " params", in.params);
  }
}

void PixelFogExecution::record(PassContext& c) {
  using rhi::BindGroupEntry;
  std::vector<BindGroupEntry> entries = {BindGroupEntry::of(0, frame_), BindGroupEntry::of(1, c.view(t_.depth)),
                                         BindGroupEntry::of(2, c.sampler(rhi::StockSampler::nearest_clamp)),
                                         BindGroupEntry::of(3, c.view(t_.fog_scattering)),
                                         BindGroupEntry::of(4, c.view(t_.fog_transmittance))};
  if (params_) entries.push_back(BindGroupEntry::of(5, params_));
  const rhi::BindGroupId group = c.bind_group(program_.layouts[0], std::move(entries));
  plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.fog_scattering));
}


}  // namespace volgraph::fog
