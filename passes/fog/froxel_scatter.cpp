// froxel_scatter (Wronski 2014, Hillaire 2015): per froxel, the light its medium scatters
// toward the camera per metre — σs·(Σ_lights p(θ)·E·V·T + L_ambient) + emission — with the
// phase function as the variant, V from the shadow map when one is wired, and T the media's
// transmittance toward the light (volumetric self-shadowing), by either of two methods:
// a march of `shadow_steps` through the media from every froxel toward every light, or,
// for the shadow map's light when an opacity_shadow_map is wired to `media_shadow`, one
// lookup in that map (the other lights keep the march).
// Shaders: shaders/froxel_scatter.comp, froxel_scatter_shadowed.comp,
// froxel_scatter_media_shadowed.comp (shaders/include/froxel_scatter_body.glsl).
#include "graph/execute/pass_execution.h"
#include "passes/fog/fog_passes.h"
#include "passes/shading/programs.h"

namespace volgraph {
namespace {

// The variants (the first is the default) and the shader's PHASE_* code of each.
const std::vector<VariantDecl> kPhaseVariants = {
    {"hg", "Henyey–Greenstein with the medium's g"},
    {"isotropic", "p = 1/4π"},
    {"rayleigh", "3/(16π)·(1 + cos²θ)"},
    {"schlick", "Schlick's approximation of HG, k = 1.55g − 0.55g³ (clamped)"},
    {"dual_hg", "forward HG (the medium's g) and backward HG (g_back) mixed by w_forward (eq. 14.17)"},
};

int32_t phase_code(std::string_view variant) {
  if (variant == "isotropic") return 0;
  if (variant == "rayleigh") return 1;
  if (variant == "schlick") return 3;
  if (variant == "dual_hg") return 4;
  return 2;  // hg
}

class FroxelScatterExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    shading::dispatch(c.encoder, c.graph_pass().name, program_, {group_, shadow_group_}, c.desc("in_scatter").extent);
  }

 private:
  void prepare(PassContext& c) {
    using namespace rhi;
    const bool shadowed = c.bound("shadow_map") && c.bound("light_view") && std::get<bool>(c.param("shadows"));
    const bool media_shadowed = shadowed && c.bound("media_shadow");
    program_ = shading::create_compute_program(c.device, media_shadowed ? "froxel_scatter_media_shadowed.comp"
                                                         : shadowed     ? "froxel_scatter_shadowed.comp"
                                                                        : "froxel_scatter.comp");
    struct {
      int32_t modes[4];
      float lobes[4];
      float volumetric[4];
    } params{{phase_code(c.variant()), std::get<bool>(c.param("skip_empty")) ? 1 : 0, 0, 0},
             {float(std::get<double>(c.param("g_back"))), float(std::get<double>(c.param("w_forward"))), 0, 0},
             {float(std::get<int64_t>(c.param("shadow_steps"))), float(std::get<double>(c.param("shadow_distance"))), 0, 0}};
    params_ = c.device.create_buffer({"froxel_scatter params", sizeof(params), buffer_usage::uniform | buffer_usage::copy_dst});
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const SamplerId nearest = c.device.create_sampler({"nearest"});
    group_ = c.device.create_bind_group({"froxel_scatter", program_.layouts[0],
                                         {BindGroupEntry::of(0, c.buffer("frame")), BindGroupEntry::of(1, c.view("media_scattering")),
                                          BindGroupEntry::of(2, c.view("media_emission")), BindGroupEntry::of(3, nearest),
                                          BindGroupEntry::of(4, c.view("in_scatter")), BindGroupEntry::of(5, params_)}});
    if (!shadowed) return;
    std::vector<BindGroupEntry> shadow = {BindGroupEntry::of(0, c.view("shadow_map")), BindGroupEntry::of(1, nearest),
                                          BindGroupEntry::of(2, c.buffer("light_view"))};
    if (media_shadowed) {
      shadow.push_back(BindGroupEntry::of(3, c.view("media_shadow")));
      shadow.push_back(BindGroupEntry::of(4, c.device.create_sampler({"media shadow", Filter::linear})));
    }
    shadow_group_ = c.device.create_bind_group({"froxel_scatter shadow", program_.layouts[1], shadow});
  }

  shading::ComputeProgram program_;
  rhi::BufferId params_;
  rhi::BindGroupId group_, shadow_group_;
};

}  // namespace

PassDecl froxel_scatter_pass() {
  PassDecl d;
  d.name = "froxel_scatter";
  d.kind = PassKind::compute;
  d.doc = "Per froxel, the light scattered toward the camera per metre: lights × phase × visibility, ambient, emission.";
  d.variants = kPhaseVariants;
  d.params = {
      param_number("g_back", -0.3, -0.999, 0.999, "", "dual_hg: the backward lobe's g"),
      param_number("w_forward", 0.7, 0, 1, "", "dual_hg: the forward lobe's weight"),
      param_bool("shadows", true, "sample the shadow map when one is wired"),
      param_int("shadow_steps", 0, 0, 256, "", "volumetric self-shadowing: steps of the march through the media toward each light not covered by media_shadow (0: off)"),
      param_number("shadow_distance", 50, 0.01, 1e5, "m", "how far that march goes toward directional lights"),
      param_bool("skip_empty", true, "froxels without scattering skip the light loop (off: to measure the saving)"),
  };
  SlotDecl in_scatter = slot_out_like("in_scatter", "media_scattering", Usage::storage_write, "scattered radiance per metre, rgb");
  d.slots = {
      slot_in("media_scattering", ResourceKind::texture3d, Usage::sampled, "from froxel_voxelize"),
      slot_in("media_emission", ResourceKind::texture3d, Usage::sampled, "from froxel_voxelize"),
      slot_in("frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block"),
      slot_optional_in("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map"),
      slot_optional_in("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view"),
      slot_optional_in("media_shadow", ResourceKind::texture3d, Usage::sampled,
                       "opacity_shadow_map's optical depth over the same light view (with shadow_map and light_view)"),
      in_scatter,
  };
  d.slots[3].format = Format::d32_float;
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new FroxelScatterExecution()); };
  return d;
}

}  // namespace volgraph
