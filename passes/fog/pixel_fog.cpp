#include "passes/fog/pixel_fog.h"

#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "shaders/bindings/depth_fog.comp.h"

namespace volgraph::fog {
namespace {
// Every per-pixel technique's shader declares include/pixel_fog.glsl's bindings; depth_fog's
// its Params block too (the others theirs at the same binding).
namespace depth_fog_shader = shaders::depth_fog_comp;
}  // namespace

void PixelFogExecution::setup(PassSetup& s) {
  const PixelFogInputs in = inputs_of_(s);
  program_ = plumbing::create_compute_program(s.device, shader_);
  FogFrameInputs frame_inputs;
  frame_inputs.grid = s.extent(t_.fog_scattering);
  frame_inputs.range = {s.scene->camera.near, s.scene->camera.far, physics::FroxelDistribution::linear};
  frame_inputs.ambient_radiance = in.ambient;
  frame_inputs.jitter = false;
  const gpu::FogFrame frame = make_fog_frame(s, 0, frame_inputs, lighting_);
  plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(program_, 0, 0, s.name() + " frame");
  frame_ = plumbing::create_uniform_block(s.device, s.name() + " frame", frame);
  if (!in.params.empty()) {
    rhi::check_uniform_block(plumbing::uniform_block_at(program_.uniform_blocks, 0, 5), in.params.size(), in.params_offsets,
                             s.name() + " params");
    params_ = plumbing::create_uniform_buffer(s.device, s.name() + " params", in.params);
  }
}

void PixelFogExecution::record(PassContext& c) {
  std::vector<rhi::BoundResource> entries = {bind(depth_fog_shader::frame, frame_), bind(depth_fog_shader::scene_depth, c.view(t_.depth)),
                                             bind(depth_fog_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                                             bind(depth_fog_shader::fog_scattering, c.view(t_.fog_scattering)),
                                             bind(depth_fog_shader::fog_transmittance, c.view(t_.fog_transmittance))};
  if (params_) entries.push_back(bind(depth_fog_shader::params, params_));
  const rhi::BindGroupId group = c.bind_group(program_, entries);
  plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.fog_scattering));
}


}  // namespace volgraph::fog
