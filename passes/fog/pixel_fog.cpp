#include "passes/fog/pixel_fog.h"

#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/shading/programs.h"

namespace volgraph::fog {
namespace {

SlotDecl fog_image(std::string name, std::string doc) {
  SlotDecl s = slot_out(std::move(name), ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                        std::move(doc));
  s.size_overridable = true;
  return s;
}

}  // namespace

std::vector<SlotDecl> pixel_fog_slots() {
  SlotDecl depth = slot_in("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (d32; 1 where nothing was drawn)");
  depth.format = Format::d32_float;
  return {depth, fog_image("fog_scattering", "in-scattered radiance toward the camera, rgb (W/(m²·sr))"),
          fog_image("fog_transmittance", "transmittance from the camera to the surface (or the far plane), rgb")};
}

namespace {

class PixelFogExecution final : public PassExecution {
 public:
  PixelFogExecution(std::string shader, PixelFogInputsOf inputs_of) : shader_(std::move(shader)), inputs_of_(inputs_of) {}

  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    shading::dispatch(c.encoder, c.graph_pass().name, program_, {group_}, c.desc("fog_scattering").extent);
  }

 private:
  void prepare(PassContext& c) {
    using rhi::BindGroupEntry;
    const std::string& name = c.graph_pass().name;
    const PixelFogInputs in = inputs_of_(c);
    program_ = shading::create_compute_program(c.device, shader_);
    FogFrameInputs frame_inputs;
    frame_inputs.grid = c.desc("fog_scattering").extent;
    frame_inputs.range = {c.scene->camera.near, c.scene->camera.far, shading::FroxelDistribution::linear};
    frame_inputs.ambient_radiance = in.ambient;
    frame_inputs.jitter = false;
    const GpuFogFrame frame = make_fog_frame(c, frame_inputs);
    std::vector<BindGroupEntry> entries = {
        BindGroupEntry::of(0, shading::create_uniform_block(c.device, name + " frame", frame)),
        BindGroupEntry::of(1, c.view("depth")), BindGroupEntry::of(2, c.device.create_sampler({"nearest"})),
        BindGroupEntry::of(3, c.view("fog_scattering")), BindGroupEntry::of(4, c.view("fog_transmittance"))};
    if (!in.params.empty()) entries.push_back(BindGroupEntry::of(5, shading::create_uniform_buffer(c.device, name + " params", in.params)));
    group_ = c.device.create_bind_group({name, program_.layouts[0], entries});
  }

  std::string shader_;
  PixelFogInputsOf inputs_of_;
  shading::ComputeProgram program_;
  rhi::BindGroupId group_;
};

}  // namespace

MakeExecution pixel_fog_execution(std::string shader, PixelFogInputsOf inputs_of) {
  return [shader, inputs_of] { return std::unique_ptr<PassExecution>(new PixelFogExecution(shader, inputs_of)); };
}

Vec3 ambient_param(const PassContext& c) { return std::get<std::array<double, 3>>(c.param("ambient")); }

}  // namespace volgraph::fog
