#include "passes/fog/pixel_fog.h"

#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"

namespace volgraph::fog {
namespace {

SlotDecl fog_image(std::string name, std::string doc) {
  SlotDecl s = slot_out(std::move(name), ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                        std::move(doc));
  s.size_overridable = true;
  return s;
}

rhi::BufferId uniform_buffer(PassContext& c, const std::string& label, std::span<const std::byte> bytes) {
  const rhi::BufferId b = c.device.create_buffer({label, bytes.size(), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  c.device.write_buffer(b, 0, bytes);
  return b;
}

}  // namespace

std::vector<SlotDecl> pixel_fog_slots() {
  SlotDecl depth = slot_in("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (d32; 1 where nothing was drawn)");
  depth.format = Format::d32_float;
  return {depth, fog_image("fog_scattering", "in-scattered radiance toward the camera, rgb (W/(m²·sr))"),
          fog_image("fog_transmittance", "transmittance from the camera to the surface (or the far plane), rgb")};
}

void PixelFogDispatch::prepare(PassContext& c, const std::string& shader, std::span<const std::byte> params, const Vec3& ambient) {
  using rhi::BindGroupEntry;
  const std::string& name = c.graph_pass().name;
  program_ = shading::create_compute_program(c.device, shader);
  FogFrameInputs inputs;
  inputs.grid = c.desc("fog_scattering").extent;
  inputs.range = {c.scene->camera.near, c.scene->camera.far, shading::FroxelDistribution::linear};
  inputs.ambient_radiance = ambient;
  inputs.jitter = false;
  const GpuFogFrame frame = make_fog_frame(c, inputs);
  frame_ = uniform_buffer(c, name + " frame", std::as_bytes(std::span(&frame, 1)));
  std::vector<BindGroupEntry> entries = {BindGroupEntry::of(0, frame_), BindGroupEntry::of(1, c.view("depth")),
                                         BindGroupEntry::of(2, c.device.create_sampler({"nearest"})),
                                         BindGroupEntry::of(3, c.view("fog_scattering")), BindGroupEntry::of(4, c.view("fog_transmittance"))};
  if (!params.empty()) entries.push_back(BindGroupEntry::of(5, uniform_buffer(c, name + " params", params)));
  group_ = c.device.create_bind_group({name, program_.layouts[0], entries});
}

void PixelFogDispatch::record(PassContext& c) const {
  c.encoder.begin_compute_pass(c.graph_pass().name);
  c.encoder.set_pipeline(program_.pipeline);
  c.encoder.set_bind_group(0, group_);
  const auto groups = program_.groups_for(c.desc("fog_scattering").extent);
  c.encoder.dispatch(groups[0], groups[1]);
  c.encoder.end_compute_pass();
}

}  // namespace volgraph::fog
