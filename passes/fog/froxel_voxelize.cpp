// froxel_voxelize (Wronski 2014, Hillaire 2015): the scene's media (σs, σa, g, emission)
// sampled at every froxel of a camera-frustum grid — `tile` × `tile` pixels (8) a froxel,
// `slices` in view depth from `near` to `far`, spaced linearly or exponentially — at the
// froxel's centre plus a per-frame jitter. Also packs the fog passes' frame block.
// Shader: shaders/froxel_voxelize.comp.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/fog/fog_passes.h"
#include "passes/shading/programs.h"

namespace volgraph {
namespace {

class FroxelVoxelizeExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    const fog::GpuFogFrame frame = fog::make_fog_frame(c, frame_inputs(c));
    const auto bytes = std::as_bytes(std::span(&frame, 1));
    c.device.write_buffer(own_frame_, 0, bytes);           // for this pass's shader
    c.encoder.update_buffer(c.buffer("frame"), 0, bytes);  // for the fog passes after it
    shading::dispatch(c.encoder, c.graph_pass().name, program_, {group_}, c.desc("media_scattering").extent);
  }

 private:
  static fog::FogFrameInputs frame_inputs(const PassContext& c) {
    fog::FogFrameInputs in;
    in.grid = c.desc("media_scattering").extent;
    in.range.near = std::get<double>(c.param("near"));
    in.range.far = std::get<double>(c.param("far"));
    in.range.distribution = std::get<std::string>(c.param("distribution")) == "linear" ? shading::FroxelDistribution::linear
                                                                                       : shading::FroxelDistribution::exponential;
    in.ambient_radiance = std::get<std::array<double, 3>>(c.param("ambient"));
    in.jitter = std::get<bool>(c.param("jitter"));
    return in;
  }

  void prepare(PassContext& c) {
    using rhi::BindGroupEntry;
    program_ = shading::create_compute_program(c.device, "froxel_voxelize.comp");
    own_frame_ = c.device.create_buffer({"froxel_voxelize frame", sizeof(fog::GpuFogFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    group_ = c.device.create_bind_group({"froxel_voxelize", program_.layouts[0],
                                         {BindGroupEntry::of(0, own_frame_), BindGroupEntry::of(1, c.view("media_scattering")),
                                          BindGroupEntry::of(2, c.view("media_absorption")),
                                          BindGroupEntry::of(3, c.view("media_emission"))}});
  }

  shading::ComputeProgram program_;
  rhi::BufferId own_frame_;
  rhi::BindGroupId group_;
};

// The media must fit the shader's block (at most kMaxMediumVolumes local volumes), and
// the range must be a range.
std::vector<ParamProblem> check_media(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params) {
  std::vector<ParamProblem> problems = fog::media_fit_problems(scene, "voxelized");
  const double near = std::get<double>(params[size_t(decl.param_index("near"))]);
  const double far = std::get<double>(params[size_t(decl.param_index("far"))]);
  if (far <= near) problems.push_back({"far", "far (" + std::to_string(far) + " m) must exceed near (" + std::to_string(near) + " m)"});
  return problems;
}

SlotDecl media_volume(std::string name, std::string doc) {
  return slot_out(std::move(name), ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                  SizeSpec::of_output_divided("tile", "slices"), std::move(doc));
}

}  // namespace

PassDecl froxel_voxelize_pass() {
  PassDecl d;
  d.name = "froxel_voxelize";
  d.kind = PassKind::compute;
  d.doc = "The scene's media at every froxel of a camera-frustum grid (`tile` × `tile` pixels a froxel, 8 by default; `slices` deep).";
  d.variants = {{"jittered", "one sample per froxel, at its centre plus a per-frame jitter (Halton 2, 3, 5) when `jitter` is on"}};
  d.params = {
      param_int("tile", 8, 1, 64, "pixels", "froxels are tile × tile pixels of the output"),
      param_int("slices", 64, 1, 512, "", "froxels in view depth"),
      param_number("near", 0.1, 1e-3, 1e5, "m", "view depth where the grid starts"),
      param_number("far", 100, 1e-2, 1e6, "m", "view depth where the grid ends"),
      param_choice("distribution", "exponential", {"exponential", "linear"}, "how slices are spaced in view depth"),
      param_bool("jitter", true, "move the sample inside its froxel every frame (frame 0 samples the centre)"),
      param_vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the media scatter (froxel_scatter adds it)"),
  };
  d.slots = {
      media_volume("media_scattering", "σs rgb (1/m) and g"),
      media_volume("media_absorption", "σa rgb (1/m)"),
      media_volume("media_emission", "emitted radiance per metre, rgb"),
      slot_out("frame", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(fog::kFogFrameBytes),
               "the camera, grid, lights and media the other fog passes use"),
  };
  d.needs = feature_bit(SceneFeature::medium);
  d.check_scene = check_media;
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new FroxelVoxelizeExecution()); };
  return d;
}

}  // namespace volgraph
