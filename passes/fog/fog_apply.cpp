// fog_apply: a per-pixel fog technique's result on the scene's colour, L = T·L_surface +
// L_scat, from the two images the technique wrote (in-scattered radiance and
// transmittance, at the frame's resolution or lower: read bilinearly at each pixel, or —
// variant depth_aware, with the scene's depth wired — by joint bilateral upsampling).
// Shaders: shaders/fog_apply_*.frag (shaders/include/fog_image_lookup*.glsl).
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/apply_draws.h"
#include "passes/fog/fog_passes.h"
#include "passes/shading/programs.h"

namespace volgraph {
namespace {

class FogApplyExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!draws_.prepared()) prepare(c);
    draws_.record(c, group_);
  }

 private:
  void prepare(PassContext& c) {
    using namespace rhi;
    const bool depth_aware = c.variant() == "depth_aware" && c.bound("depth");
    if (depth_aware) {
      draws_.prepare(c, "fog_apply_transmittance_depth_aware.frag", "fog_apply_scattering_depth_aware.frag");
    } else {
      draws_.prepare(c, "fog_apply_transmittance.frag", "fog_apply_scattering.frag");
    }
    const Extent size = c.desc("color").extent;
    const Camera& camera = c.scene->camera;
    const float frame[4] = {float(size.width), float(size.height), float(camera.near), float(camera.far)};
    const std::string& name = c.graph_pass().name;
    std::vector<BindGroupEntry> entries = {BindGroupEntry::of(0, c.view("fog_scattering")), BindGroupEntry::of(1, c.view("fog_transmittance")),
                                           BindGroupEntry::of(3, shading::create_uniform_block(c.device, name + " frame", frame))};
    if (depth_aware) {
      entries.push_back(BindGroupEntry::of(2, c.device.create_sampler({"nearest"})));
      entries.push_back(BindGroupEntry::of(4, c.view("depth")));
    } else {
      entries.push_back(BindGroupEntry::of(2, c.device.create_sampler({"bilinear", Filter::linear})));
    }
    group_ = c.device.create_bind_group({name, draws_.layout(), entries});
  }

  fog::ApplyDraws draws_;
  rhi::BindGroupId group_;
};

}  // namespace

PassDecl fog_apply_pass() {
  PassDecl d;
  d.name = "fog_apply";
  d.kind = PassKind::graphics;
  d.doc = "Applies a per-pixel fog technique's in-scattering and transmittance images to the scene's colour.";
  d.variants = {
      {"bilinear", "the images read bilinearly at each pixel's centre (upsamples a lower resolution)"},
      {"depth_aware", "joint bilateral upsampling (Kopf et al. 2007) guided by the scene's `depth` (bilinear without it)"},
  };
  SlotDecl depth = slot_optional_in("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth, for depth_aware");
  depth.format = Format::d32_float;
  d.slots = {
      slot_inout("color", ResourceKind::texture2d, Usage::color_attachment_load, "the scene's linear radiance"),
      slot_in("fog_scattering", ResourceKind::texture2d, Usage::sampled, "in-scattered radiance toward the camera, rgb"),
      slot_in("fog_transmittance", ResourceKind::texture2d, Usage::sampled, "transmittance from the camera to the surface, rgb"),
      depth,
  };
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new FogApplyExecution()); };
  return d;
}

}  // namespace volgraph
