// froxel_scatter (Wronski 2014, Hillaire 2015): per froxel, the light its medium scatters
// toward the camera per metre — σs·(Σ_lights p(θ)·E·V·T + L_ambient) + emission — with the
// phase function as the variant, V from the shadow map when one is wired, and T the media's
// transmittance toward the light (volumetric self-shadowing): the global and height fog's
// in closed form, always (shaders/include/light_transmittance.glsl), times the local
// volumes' by either of two methods: from every froxel toward every light, each volume's
// chord times its mean density over `shadow_steps` stratified samples (exact for a volume
// without edge fade or noise; 0: none), or, for the shadow map's light when an
// opacity_shadow_map is wired to `media_shadow`, one lookup in that map (the other lights
// keep the chords). With a translucent_shadow_map of the same light view wired, the
// translucent casters tint that light's V (RTR4 §14.5.1: the fog behind coloured glass
// carries its colour). With a cloud_shadow_map wired, the cloud layer above dims the sun's V
// by exp(−τ) (shafts of fog light between the clouds' shadows).
// Shaders: shaders/froxel_scatter.comp and froxel_scatter_*shadowed.comp, one per set of maps
// wired (their defines over shaders/include/fog_light_visibility.glsl; the body
// shaders/include/froxel_scatter_body.glsl).
#include <cstddef>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "passes/fog/phase_variants.h"
#include "shaders/bindings/froxel_scatter.comp.h"
#include "shaders/bindings/froxel_scatter_media_translucent_shadowed_cloud_shadowed.comp.h"
#include "shaders/include/cloud_shadow_view.h"

namespace volgraph {
namespace {

namespace froxel_scatter_shader = shaders::froxel_scatter_comp;
// Every map's bindings in set 1, numbered alike in every permutation (fog_light_visibility.glsl).
namespace froxel_scatter_maps_shader = shaders::froxel_scatter_media_translucent_shadowed_cloud_shadowed_comp;

struct FroxelScatterTable : fog::PhaseTable {
  FroxelScatterTable()
      : PhaseTable("froxel_scatter", PassKind::compute,
                  "Per froxel, the light scattered toward the camera per metre: lights × phase × visibility, ambient, emission.") {
    decl.needs = feature_bit(SceneFeature::medium);
  }
  // The phase variants and dual_hg's lobes come first (fog::PhaseTable); then:
  // Parameters.
  ParamHandle<bool> shadows = flag("shadows", true, "sample the shadow map when one is wired");
  ParamHandle<int64_t> shadow_steps = integer("shadow_steps", 8, 0, 256, "",
      "samples of each local volume's density along its chord toward each light not covered by media_shadow (a volume without "
      "edge fade or noise: its exact chord; 0: the volumes do not shadow; the global and height fog dim every light in closed form)");
  ParamHandle<double> shadow_distance = number("shadow_distance", 50, 0.01, 1e5, "m", "how far toward directional lights the volumes shadow");
  ParamHandle<bool> skip_empty = flag("skip_empty", true, "froxels without scattering skip the light loop (off: to measure the saving)");
  // Slots.
  SlotHandle media_scattering = input("media_scattering", ResourceKind::texture3d, Usage::sampled, "from froxel_voxelize");
  SlotHandle media_emission = input("media_emission", ResourceKind::texture3d, Usage::sampled, "from froxel_voxelize");
  SlotHandle frame = input("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block");
  SlotHandle shadow_map = optional_input("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map",
                                         {.format = Format::d32_float});
  SlotHandle light_view = optional_input("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view");
  SlotHandle media_shadow = optional_input("media_shadow", ResourceKind::texture3d, Usage::sampled,
                                           "opacity_shadow_map's optical depth over the same light view (with shadow_map and light_view)");
  SlotHandle translucent_shadow = optional_input("translucent_shadow", ResourceKind::texture2d, Usage::sampled,
                                                 "translucent_shadow_map's transmittance over the same light view: translucent casters tint that light");
  SlotHandle translucent_shadow_depth = optional_input("translucent_shadow_depth", ResourceKind::texture2d, Usage::sampled,
                                                       "translucent_shadow_map's depth: only froxels behind its casters are tinted",
                                                       {.format = Format::d32_float});
  SlotHandle cloud_shadow = optional_input("cloud_shadow", ResourceKind::texture2d, Usage::sampled,
                                           "cloud_shadow_map's optical depth: the cloud layer dims the sun by exp(−τ)",
                                           {.format = Format::rgba16_float});
  SlotHandle cloud_shadow_view = optional_input("cloud_shadow_view", ResourceKind::buffer, Usage::uniform_read,
                                                "cloud_shadow_map's view (where its square lies, toward which sun)");
  SlotHandle in_scatter = output_like("in_scatter", media_scattering, Usage::storage_write, "scattered radiance per metre, rgb");
};

class FroxelScatterExecution final : public PassExecution {
 public:
  explicit FroxelScatterExecution(const FroxelScatterTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    shadowed_ = s.bound(t_.shadow_map) && s.bound(t_.light_view) && s.param(t_.shadows);
    media_shadowed_ = shadowed_ && s.bound(t_.media_shadow);
    translucent_shadowed_ = shadowed_ && s.bound(t_.translucent_shadow) && s.bound(t_.translucent_shadow_depth);
    cloud_shadowed_ = s.bound(t_.cloud_shadow) && s.bound(t_.cloud_shadow_view);
    program_ = plumbing::create_compute_program(s.device, shader_name());
    if (cloud_shadowed_)
      plumbing::check_wrapped_uniform_mirror<gpu::CloudShadowView>(program_, froxel_scatter_maps_shader::cloud_shadow_view,
                                                                   s.name() + " cloud_shadow_view");
    const gpu::FroxelScatterParams params{{s.variant().shader_code, s.param(t_.skip_empty) ? 1 : 0, 0, 0},
                                        {float(s.param(t_.g_back)), float(s.param(t_.w_forward)), 0, 0},
                                        {float(s.param(t_.shadow_steps)), float(s.param(t_.shadow_distance)), 0, 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, froxel_scatter_shader::params, s.name() + " params", params);
  }

  // Shadow map, opacity map (media), translucent map, cloud shadow: each shader holds the ones wired.
  std::string shader_name() const {
    std::string name = "froxel_scatter";
    if (shadowed_) name += media_shadowed_ ? (translucent_shadowed_ ? "_media_translucent_shadowed" : "_media_shadowed")
                                           : (translucent_shadowed_ ? "_translucent_shadowed" : "_shadowed");
    if (cloud_shadowed_) name += "_cloud_shadowed";
    return name + ".comp";
  }

  void record(PassContext& c) override {
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    // Every variant's shader declares froxel_scatter_body.glsl's set 0; the shadowed ones set 1.
    const rhi::BindGroupId media = c.bind_group(program_, {bind(froxel_scatter_shader::frame, c.buffer(t_.frame)),
                                                           bind(froxel_scatter_shader::media_scattering, c.view(t_.media_scattering)),
                                                           bind(froxel_scatter_shader::media_emission, c.view(t_.media_emission)), bind(froxel_scatter_shader::nearest, nearest),
                                                           bind(froxel_scatter_shader::in_scatter, c.view(t_.in_scatter)), bind(froxel_scatter_shader::params, params_)});
    rhi::BindGroupId maps;
    if (shadowed_ || cloud_shadowed_) maps = c.bind_group(program_, map_entries(c, nearest));
    plumbing::dispatch(c.encoder, c.name(), program_, {media, maps}, c.extent(t_.in_scatter));
  }

 private:
  // Set 1 as wired: the shadow map with the media's and the translucent casters' maps, the cloud shadow.
  std::vector<rhi::BoundResource> map_entries(PassContext& c, rhi::SamplerId nearest) const {
    namespace shader = froxel_scatter_maps_shader;
    std::vector<rhi::BoundResource> entries;
    if (shadowed_) {
      entries = {bind(shader::shadow_depth, c.view(t_.shadow_map)), bind(shader::shadow_sampler, nearest),
                 bind(shader::shadow, c.buffer(t_.light_view))};
    }
    if (media_shadowed_) {
      entries.push_back(bind(shader::media_shadow, c.view(t_.media_shadow)));
      entries.push_back(bind(shader::media_shadow_sampler, c.sampler(rhi::StockSampler::linear_clamp)));
    }
    if (translucent_shadowed_) {
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

  const FroxelScatterTable& t_;
  bool shadowed_ = false, media_shadowed_ = false, translucent_shadowed_ = false, cloud_shadowed_ = false;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(FroxelScatterTable, FroxelScatterExecution);

}  // namespace volgraph
