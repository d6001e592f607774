// froxel_voxelize (Wronski 2014, Hillaire 2015): the scene's media (σs, σa, g, emission)
// at every froxel of a camera-frustum grid — `tile` × `tile` pixels (8) a froxel,
// `slices` in view depth from `near` to `far`, spaced linearly or exponentially — averaged
// over the froxel's depth range along its ray: exactly for the global fog, the height fog
// and volumes without edge fade or noise, by stratified sub-samples inside faded or noisy
// volumes (shaders/include/media_average.glsl ↔ physics/media_average.h). The ray and the
// sub-samples move by a per-frame jitter. Also packs the fog passes' frame block.
// Shader: shaders/froxel_voxelize.comp.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "shaders/bindings/froxel_voxelize.comp.h"

namespace volgraph {
namespace {

namespace froxel_voxelize_shader = shaders::froxel_voxelize_comp;

struct FroxelVoxelizeTable : PassTable {
  FroxelVoxelizeTable();
  // Variants.
  VariantHandle jittered =
      variant("jittered",
              "the media averaged over each froxel's depth along its ray (exact for fog, height fog and uniform volumes; 4 stratified "
              "sub-samples in faded or noisy volumes), the ray and the sub-samples moved by a per-frame jitter (Halton 2, 3, 5) when `jitter` is on");
  // Parameters.
  ParamHandle<int64_t> tile = integer("tile", 8, 1, 64, "pixels", "froxels are tile × tile pixels of the output");
  ParamHandle<int64_t> slices = integer("slices", 64, 1, 512, "", "froxels in view depth");
  ParamHandle<double> near = number("near", 0.1, 1e-3, 1e5, "m", "view depth where the grid starts");
  ParamHandle<double> far = number("far", 100, 1e-2, 1e6, "m", "view depth where the grid ends");
  ChoiceHandle<physics::FroxelDistribution> distribution =
      choice("distribution", physics::FroxelDistribution::exponential,
             {{physics::FroxelDistribution::exponential, "exponential"}, {physics::FroxelDistribution::linear, "linear"}},
             "how slices are spaced in view depth");
  ParamHandle<bool> jitter = flag("jitter", true,
                                 "move each froxel's ray across it and its sub-samples along it every frame (frame 0: the centre ray, the strata's centres)");
  ParamHandle<std::array<double, 3>> ambient =
      vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the media scatter (froxel_scatter adds it)");
  // Slots.
  SlotHandle media_scattering = media_volume("media_scattering", "σs rgb (1/m) and g");
  SlotHandle media_absorption = media_volume("media_absorption", "σa rgb (1/m)");
  SlotHandle media_emission = media_volume("media_emission", "emitted radiance per metre, rgb");
  SlotHandle frame = output("frame", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(fog::kFogFrameBytes),
                            "the camera, grid, lights and media the other fog passes use");

 private:
  SlotHandle media_volume(std::string name, std::string doc) {
    return output(std::move(name), ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                  SizeSpec::of_output_divided(tile, slices), std::move(doc));
  }
};

// The media must fit the shader's block (at most kMaxMediumVolumes local volumes), and
// the range must be a range.
std::vector<ParamProblem> check_media(const PassDecl&, const Scene& scene, const std::vector<ParamValue>& params) {
  static const FroxelVoxelizeTable table;
  std::vector<ParamProblem> problems = fog::media_fit_problems(scene, "voxelized");
  const double near = param_in(params, table.near);
  const double far = param_in(params, table.far);
  if (far <= near) problems.push_back({"far", "far (" + std::to_string(far) + " m) must exceed near (" + std::to_string(near) + " m)"});
  return problems;
}

FroxelVoxelizeTable::FroxelVoxelizeTable()
    : PassTable("froxel_voxelize", PassKind::compute,
                "The scene's media at every froxel of a camera-frustum grid (`tile` × `tile` pixels a froxel, 8 by default; `slices` deep).") {
  decl.needs = feature_bit(SceneFeature::medium);
  decl.check_scene = check_media;
}

class FroxelVoxelizeExecution final : public PassExecution {
 public:
  explicit FroxelVoxelizeExecution(const FroxelVoxelizeTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "froxel_voxelize.comp");
    // Written every frame, here and to `frame` for the fog passes after it: checked once.
    plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(program_, 0, 0, s.name() + " frame");
    own_frame_ = s.device.create_buffer({s.name() + " frame", sizeof(gpu::FogFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    inputs_.grid = s.extent(t_.media_scattering);
    inputs_.range.near = s.param(t_.near);
    inputs_.range.far = s.param(t_.far);
    inputs_.range.distribution = s.param(t_.distribution);
    inputs_.ambient_radiance = s.param(t_.ambient);
    inputs_.jitter = s.param(t_.jitter);
  }

  void record(PassContext& c) override {
    const gpu::FogFrame frame = fog::make_fog_frame(c, c.frame, inputs_, lighting_);
    const auto bytes = std::as_bytes(std::span(&frame, 1));
    c.device.write_buffer(own_frame_, 0, bytes);               // for this pass's shader
    c.encoder.update_buffer(c.buffer(t_.frame), 0, bytes);  // for the fog passes after it
    const rhi::BindGroupId group = c.bind_group(program_, {bind(froxel_voxelize_shader::frame, own_frame_), bind(froxel_voxelize_shader::media_scattering, c.view(t_.media_scattering)),
                                                           bind(froxel_voxelize_shader::media_absorption, c.view(t_.media_absorption)),
                                                           bind(froxel_voxelize_shader::media_emission, c.view(t_.media_emission))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.media_scattering));
  }

 private:
  const FroxelVoxelizeTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId own_frame_;
  fog::FogFrameInputs inputs_;
  plumbing::SceneLighting lighting_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(FroxelVoxelizeTable, FroxelVoxelizeExecution);

}  // namespace volgraph
