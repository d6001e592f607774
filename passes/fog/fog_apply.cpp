// fog_apply: a per-pixel fog technique's result on the scene's colour, L = T·L_surface +
// L_scat, from the two images the technique wrote (in-scattered radiance and
// transmittance, at the frame's resolution or lower: read bilinearly at each pixel, or —
// variant depth_aware, which needs the scene's depth wired — by joint bilateral upsampling).
// Shaders: shaders/fog_apply_*.frag (shaders/include/fog_image_lookup*.glsl).
#include <array>

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
    rhi::BindGroupId& group = groups_[c.parity()];  // the images may be history pairs' (pixel_temporal)
    if (!group) group = make_group(c);
    draws_.record(c, group);
  }

 private:
  void prepare(PassContext& c) {
    using namespace rhi;
    depth_aware_ = c.variant() == "depth_aware";  // the loader made sure `depth` is wired
    if (depth_aware_) {
      draws_.prepare(c, "fog_apply_transmittance_depth_aware.frag", "fog_apply_scattering_depth_aware.frag");
    } else {
      draws_.prepare(c, "fog_apply_transmittance.frag", "fog_apply_scattering.frag");
    }
    const Extent size = c.desc("color").extent;
    const Camera& camera = c.scene->camera;
    const float frame[4] = {float(size.width), float(size.height), float(camera.near), float(camera.far)};
    frame_ = shading::create_uniform_block(c.device, c.graph_pass().name + " frame", frame);
    sampler_ = depth_aware_ ? c.device.create_sampler({"nearest"}) : c.device.create_sampler({"bilinear", Filter::linear});
  }

  rhi::BindGroupId make_group(PassContext& c) {
    using rhi::BindGroupEntry;
    std::vector<BindGroupEntry> entries = {BindGroupEntry::of(0, c.view("fog_scattering")), BindGroupEntry::of(1, c.view("fog_transmittance")),
                                           BindGroupEntry::of(2, sampler_), BindGroupEntry::of(3, frame_)};
    if (depth_aware_) entries.push_back(BindGroupEntry::of(4, c.view("depth")));
    return c.device.create_bind_group({c.graph_pass().name, draws_.layout(), entries});
  }

  fog::ApplyDraws draws_;
  bool depth_aware_ = false;
  rhi::BufferId frame_;
  rhi::SamplerId sampler_;
  std::array<rhi::BindGroupId, 2> groups_;
};

}  // namespace

PassDecl fog_apply_pass() {
  PassDecl d;
  d.name = "fog_apply";
  d.kind = PassKind::graphics;
  d.doc = "Applies a per-pixel fog technique's in-scattering and transmittance images to the scene's colour.";
  d.variants = {
      {"bilinear", "the images read bilinearly at each pixel's centre (upsamples a lower resolution)"},
      {"depth_aware", "joint bilateral upsampling (Kopf et al. 2007) guided by the scene's `depth`", {"depth"}},
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
  d.parity_bind_groups = true;
  return d;
}

}  // namespace volgraph
