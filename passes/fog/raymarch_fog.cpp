// raymarch_fog: per-pixel ray marching through the scene's media (Tóth & Umenhoffer
// 2009; Hillaire 2015's energy-conserving step). Per pixel of its output — the frame's
// resolution or half of it — a march from the camera to the scene's surface (to view
// depth `max_distance` where there is none) in `steps` equal steps sampled at a
// per-pixel jittered point (interleaved gradient noise, per frame), integrated by
// Hillaire's step (eq. 14.16) whatever the variant; per sample the media and their
// in-scattering (shaders/include/in_scattering.glsl, shared with froxel_scatter): every
// light through the phase function — the variant, the same five as froxel_scatter's, codes
// from shaders/include/phase_codes.h —, the shadow map's visibility when one is wired, and
// volumetric shadows: the global and height fog toward each light in closed form, always,
// and the local volumes by their chords toward it, each volume's density sampled
// `shadow_steps` times along its chord (exact without edge fade or noise; 0: none). Writes
// fog_apply's two images: in-scattered radiance and transmittance.
// With a translucent_shadow_map of the shadow map's light view wired, the translucent casters
// tint that light at each sample (RTR4 §14.5.1).
// With a cloud_shadow_map wired, the cloud layer above dims the sun at each sample by exp(−τ).
// Shaders: shaders/raymarch_fog.comp and raymarch_fog_*shadowed.comp, one per set of maps
// wired (their defines over shaders/include/fog_light_visibility.glsl; the march
// shaders/include/raymarch_fog_body.glsl, in_scattering.glsl, light_transmittance.glsl).
#include <string>
#include <vector>
#include <cstddef>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "passes/fog/phase_variants.h"
#include "shaders/bindings/raymarch_fog_translucent_shadowed_cloud_shadowed.comp.h"
#include "shaders/include/cloud_shadow_view.h"

namespace volgraph {
namespace {

// Every binding by the fullest permutation's names: the others number theirs alike (fog_light_visibility.glsl).
namespace raymarch_fog_shader = shaders::raymarch_fog_translucent_shadowed_cloud_shadowed_comp;

// The outputs' size (parameter "resolution").
enum class Resolution : uint8_t { full, half };
int64_t divisor_of(Resolution r) { return r == Resolution::half ? 2 : 1; }

struct RaymarchFogTable : fog::PhaseTable {
  RaymarchFogTable()
      : PhaseTable("raymarch_fog", PassKind::compute,
                  "Per-pixel ray marching through the media to the scene's depth (equal steps, a per-pixel jittered sample in each, "
                  "Hillaire's energy-conserving step): in-scattering (the phase variant, shadow map, volumetric shadows) and transmittance.") {
    decl.needs = feature_bit(SceneFeature::medium);
    decl.check_scene = [](const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
      return fog::media_fit_problems(scene, "marched");
    };
  }
  // The phase variants and dual_hg's lobes come first (fog::PhaseTable); then:
  // Parameters.
  ParamHandle<int64_t> steps = integer("steps", 64, 1, 4096, "", "equal steps from the camera to the surface");
  ParamHandle<int64_t> shadow_steps =
      integer("shadow_steps", 8, 0, 1024, "",
              "samples of each local volume's density along its chord toward each light (a volume without edge fade or noise: "
              "its exact chord; 0: the volumes do not shadow; the global and height fog dim every light in closed form)");
  ParamHandle<double> max_distance = number("max_distance", 100, 1e-3, 1e7, "m",
                                            "view depth the march reaches where no surface is (at most the camera's far plane)");
  ParamHandle<double> shadow_distance =
      number("shadow_distance", 50, 1e-3, 1e7, "m", "how far toward a directional light the volumes shadow");
  ChoiceHandle<Resolution> resolution = choice("resolution", Resolution::full, {{Resolution::full, "full"}, {Resolution::half, "half"}},
                                               "the outputs' size: the frame's or half of it in x and y");
  ParamHandle<bool> jitter =
      flag("jitter", true, "sample each step at a per-pixel, per-frame point (interleaved gradient noise); off: its midpoint");
  ParamHandle<bool> shadows = flag("shadows", true, "sample the shadow map when one is wired");
  ParamHandle<std::array<double, 3>> ambient = vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the media scatter");
  // Slots.
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth", {.format = Format::d32_float});
  SlotHandle shadow_map = optional_input("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map",
                                         {.format = Format::d32_float});
  SlotHandle light_view = optional_input("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view");
  SlotHandle translucent_shadow = optional_input("translucent_shadow", ResourceKind::texture2d, Usage::sampled,
                                                 "translucent_shadow_map's transmittance over the same light view: translucent casters tint that light");
  SlotHandle translucent_shadow_depth = optional_input("translucent_shadow_depth", ResourceKind::texture2d, Usage::sampled,
                                                       "translucent_shadow_map's depth: only samples behind its casters are tinted",
                                                       {.format = Format::d32_float});
  SlotHandle cloud_shadow = optional_input("cloud_shadow", ResourceKind::texture2d, Usage::sampled,
                                           "cloud_shadow_map's optical depth: the cloud layer dims the sun by exp(−τ)",
                                           {.format = Format::rgba16_float});
  SlotHandle cloud_shadow_view = optional_input("cloud_shadow_view", ResourceKind::buffer, Usage::uniform_read,
                                                "cloud_shadow_map's view (where its square lies, toward which sun)");
  SlotHandle fog_scattering = output("fog_scattering", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                     fog_image_size(), "in-scattered radiance toward the camera, rgb");
  SlotHandle fog_transmittance = output("fog_transmittance", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                        fog_image_size(), "transmittance from the camera to the surface, rgb");

 private:
  SizeSpec fog_image_size() const { return SizeSpec::of_output_divided_by_choice(resolution, divisor_of); }
};

class RaymarchFogExecution final : public PassExecution {
 public:
  explicit RaymarchFogExecution(const RaymarchFogTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    using namespace rhi;
    shadowed_ = s.bound(t_.shadow_map) && s.bound(t_.light_view) && s.param(t_.shadows);
    tinted_ = shadowed_ && s.bound(t_.translucent_shadow) && s.bound(t_.translucent_shadow_depth);
    cloud_shadowed_ = s.bound(t_.cloud_shadow) && s.bound(t_.cloud_shadow_view);
    program_ = plumbing::create_compute_program(s.device, shader_name());
    if (cloud_shadowed_)
      plumbing::check_wrapped_uniform_mirror<gpu::CloudShadowView>(program_, raymarch_fog_shader::cloud_shadow_view, s.name() + " cloud_shadow_view");
    plumbing::check_wrapped_uniform_mirror<gpu::RaymarchParams>(program_, raymarch_fog_shader::params, s.name() + " params");
    plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(program_, 0, 0, s.name() + " frame");
    phase_ = {s.variant().shader_code, float(s.param(t_.g_back)), float(s.param(t_.w_forward))};
    frame_ = s.device.create_buffer({"raymarch_fog frame", sizeof(gpu::FogFrame), buffer_usage::uniform | buffer_usage::copy_dst});
    params_ = s.device.create_buffer({"raymarch_fog params", sizeof(gpu::RaymarchParams), buffer_usage::uniform | buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    const gpu::FogFrame frame = fog::make_fog_frame(c, c.frame, frame_inputs(c), lighting_);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    const gpu::RaymarchParams params = march_params(c);
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    // Both variants' shaders declare raymarch_fog_body.glsl's set 0; the shadowed one set 1.
    const rhi::BindGroupId group = c.bind_group(program_, {bind(raymarch_fog_shader::frame, frame_), bind(raymarch_fog_shader::scene_depth, c.view(t_.depth)),
                                                           bind(raymarch_fog_shader::nearest, nearest), bind(raymarch_fog_shader::fog_scattering, c.view(t_.fog_scattering)),
                                                           bind(raymarch_fog_shader::fog_transmittance, c.view(t_.fog_transmittance)),
                                                           bind(raymarch_fog_shader::params, params_)});
    rhi::BindGroupId maps;
    if (shadowed_ || cloud_shadowed_) maps = c.bind_group(program_, map_entries(c, nearest));
    plumbing::dispatch(c.encoder, c.name(), program_, {group, maps}, c.extent(t_.fog_scattering));
  }

 private:
  // Shadow map, translucent casters' map, cloud shadow: each shader holds the ones wired.
  std::string shader_name() const {
    std::string name = "raymarch_fog";
    if (shadowed_) name += tinted_ ? "_translucent_shadowed" : "_shadowed";
    if (cloud_shadowed_) name += "_cloud_shadowed";
    return name + ".comp";
  }

  // Set 1 as wired.
  std::vector<rhi::BoundResource> map_entries(PassContext& c, rhi::SamplerId nearest) const {
    namespace shader = raymarch_fog_shader;
    std::vector<rhi::BoundResource> entries;
    if (shadowed_) {
      entries = {bind(shader::shadow_depth, c.view(t_.shadow_map)), bind(shader::shadow_sampler, nearest),
                 bind(shader::shadow, c.buffer(t_.light_view))};
    }
    if (tinted_) {
      entries.push_back(bind(shader::translucent_shadow, c.view(t_.translucent_shadow)));
      entries.push_back(bind(shader::translucent_shadow_depth, c.view(t_.translucent_shadow_depth)));
    }
    if (cloud_shadowed_) {
      entries.push_back(bind(shader::cloud_shadow, c.view(t_.cloud_shadow)));
      entries.push_back(bind(shader::cloud_shadow_sampler, c.sampler(rhi::StockSampler::linear_clamp)));
      entries.push_back(bind(shader::cloud_shadow_view, c.buffer(t_.cloud_shadow_view)));
    }
    return entries;
  }

  // The frame block's camera, lights, media and ambient radiance (its froxel grid is
  // unused here: the output's size stands in for it).
  fog::FogFrameInputs frame_inputs(const PassContext& c) const {
    fog::FogFrameInputs in;
    in.grid = c.extent(t_.fog_scattering);
    in.range.near = c.scene->camera.near;
    in.range.far = c.scene->camera.far;
    in.ambient_radiance = c.param(t_.ambient);
    in.jitter = false;
    return in;
  }

  gpu::RaymarchParams march_params(const PassContext& c) const {
    gpu::RaymarchParams p{};
    p.steps[0] = int32_t(c.param(t_.steps));
    p.steps[1] = int32_t(c.param(t_.shadow_steps));
    // Where no surface is, never past the camera's far plane: the scene ends there (as in the reference).
    p.distances[0] = float(std::min(c.param(t_.max_distance), c.scene->camera.far));
    p.distances[1] = float(c.param(t_.shadow_distance));
    p.jitter[0] = c.param(t_.jitter) ? 1.0f : 0.0f;
    p.jitter[1] = float(c.frame % 64);
    p.modes[0] = phase_.code;
    p.lobes[0] = phase_.g_back;
    p.lobes[1] = phase_.w_forward;
    return p;
  }

  // The phase variant (its code) and the dual-lobe HG's parameters, read once.
  struct Phase {
    int32_t code = PHASE_HG;
    float g_back = 0, w_forward = 0;
  };

  const RaymarchFogTable& t_;
  bool shadowed_ = false, tinted_ = false, cloud_shadowed_ = false;
  Phase phase_;
  plumbing::ComputeProgram program_;
  plumbing::SceneLighting lighting_;
  rhi::BufferId frame_, params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(RaymarchFogTable, RaymarchFogExecution);

}  // namespace volgraph
