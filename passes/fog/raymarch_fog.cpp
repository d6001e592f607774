// raymarch_fog: per-pixel ray marching through the scene's media (Tóth & Umenhoffer
// 2009; Hillaire 2015's energy-conserving step). Per pixel of its output — the frame's
// resolution or half of it — a march from the camera to the scene's surface (to view
// depth `max_distance` where there is none) in `steps` equal steps sampled at a
// per-pixel jittered point (interleaved gradient noise, per frame); per sample the media,
// every light through the medium's HG phase, the shadow map's visibility when one is
// wired, and volumetric shadows by a secondary march of `shadow_steps` toward each
// light. Writes fog_apply's two images: in-scattered radiance and transmittance.
// Shaders: shaders/raymarch_fog.comp, raymarch_fog_shadowed.comp
// (shaders/include/raymarch_fog_body.glsl, light_transmittance.glsl).
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/fog/fog_passes.h"
#include "passes/shading/programs.h"

namespace volgraph {
namespace {

// std140 mirror of raymarch_fog_body.glsl's Params block.
struct GpuRaymarchParams {
  int32_t steps[4];
  float distances[4];
  float jitter[4];
};

class RaymarchFogExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    const fog::GpuFogFrame frame = fog::make_fog_frame(c, frame_inputs(c));
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    const GpuRaymarchParams params = march_params(c);
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    shading::dispatch(c.encoder, c.graph_pass().name, program_, {group_, shadow_group_}, c.desc("fog_scattering").extent);
  }

 private:
  // The frame block's camera, lights, media and ambient radiance (its froxel grid is
  // unused here: the output's size stands in for it).
  static fog::FogFrameInputs frame_inputs(const PassContext& c) {
    fog::FogFrameInputs in;
    in.grid = c.desc("fog_scattering").extent;
    in.range.near = c.scene->camera.near;
    in.range.far = c.scene->camera.far;
    in.ambient_radiance = std::get<std::array<double, 3>>(c.param("ambient"));
    in.jitter = false;
    return in;
  }

  static GpuRaymarchParams march_params(const PassContext& c) {
    GpuRaymarchParams p{};
    p.steps[0] = int32_t(std::get<int64_t>(c.param("steps")));
    p.steps[1] = int32_t(std::get<int64_t>(c.param("shadow_steps")));
    // Where no surface is, never past the camera's far plane: the scene ends there (as in the reference).
    p.distances[0] = float(std::min(std::get<double>(c.param("max_distance")), c.scene->camera.far));
    p.distances[1] = float(std::get<double>(c.param("shadow_distance")));
    p.jitter[0] = std::get<bool>(c.param("jitter")) ? 1.0f : 0.0f;
    p.jitter[1] = float(c.frame % 64);
    return p;
  }

  void prepare(PassContext& c) {
    using namespace rhi;
    const bool shadowed = c.bound("shadow_map") && c.bound("light_view") && std::get<bool>(c.param("shadows"));
    program_ = shading::create_compute_program(c.device, shadowed ? "raymarch_fog_shadowed.comp" : "raymarch_fog.comp");
    frame_ = c.device.create_buffer({"raymarch_fog frame", sizeof(fog::GpuFogFrame), buffer_usage::uniform | buffer_usage::copy_dst});
    params_ = c.device.create_buffer({"raymarch_fog params", sizeof(GpuRaymarchParams), buffer_usage::uniform | buffer_usage::copy_dst});
    const SamplerId nearest = c.device.create_sampler({"nearest"});
    group_ = c.device.create_bind_group({"raymarch_fog", program_.layouts[0],
                                         {BindGroupEntry::of(0, frame_), BindGroupEntry::of(1, c.view("depth")),
                                          BindGroupEntry::of(2, nearest), BindGroupEntry::of(3, c.view("fog_scattering")),
                                          BindGroupEntry::of(4, c.view("fog_transmittance")), BindGroupEntry::of(5, params_)}});
    if (!shadowed) return;
    shadow_group_ = c.device.create_bind_group({"raymarch_fog shadow", program_.layouts[1],
                                                {BindGroupEntry::of(0, c.view("shadow_map")), BindGroupEntry::of(1, nearest),
                                                 BindGroupEntry::of(2, c.buffer("light_view"))}});
  }

  shading::ComputeProgram program_;
  rhi::BufferId frame_, params_;
  rhi::BindGroupId group_, shadow_group_;
};

SlotDecl fog_image(std::string name, std::string doc) {
  return slot_out(std::move(name), ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                  SizeSpec::of_output_divided_by_choice("resolution", {{"full", 1}, {"half", 2}}), std::move(doc));
}

}  // namespace

PassDecl raymarch_fog_pass() {
  PassDecl d;
  d.name = "raymarch_fog";
  d.kind = PassKind::compute;
  d.doc = "Per-pixel ray marching through the media to the scene's depth: in-scattering (HG, shadow map, volumetric shadows) and transmittance.";
  d.variants = {{"hillaire", "equal steps with a per-pixel jittered sample in each, Hillaire's energy-conserving step (eq. 14.16)"}};
  d.params = {
      param_int("steps", 64, 1, 4096, "", "equal steps from the camera to the surface"),
      param_int("shadow_steps", 0, 0, 1024, "", "steps of the march toward each light for volumetric shadows (0: off)"),
      param_number("max_distance", 100, 1e-3, 1e7, "m", "view depth the march reaches where no surface is (at most the camera's far plane)"),
      param_number("shadow_distance", 50, 1e-3, 1e7, "m", "how far the march toward a directional light goes"),
      param_choice("resolution", "full", {"full", "half"}, "the outputs' size: the frame's or half of it in x and y"),
      param_bool("jitter", true, "sample each step at a per-pixel, per-frame point (interleaved gradient noise); off: its midpoint"),
      param_bool("shadows", true, "sample the shadow map when one is wired"),
      param_vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the media scatter"),
  };
  d.slots = {
      slot_in("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth"),
      slot_optional_in("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map"),
      slot_optional_in("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view"),
      fog_image("fog_scattering", "in-scattered radiance toward the camera, rgb"),
      fog_image("fog_transmittance", "transmittance from the camera to the surface, rgb"),
  };
  d.slots[0].format = Format::d32_float;
  d.slots[1].format = Format::d32_float;
  d.needs = feature_bit(SceneFeature::medium);
  d.check_scene = [](const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) { return fog::media_fit_problems(scene, "marched"); };
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new RaymarchFogExecution()); };
  return d;
}

}  // namespace volgraph
