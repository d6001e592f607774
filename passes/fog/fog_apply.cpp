// fog_apply: a per-pixel fog technique's result on the scene's colour, L = T·L_surface +
// L_scat, from the two images the technique wrote (in-scattered radiance and
// transmittance, at the frame's resolution or lower: read bilinearly at each pixel).
// Shaders: shaders/fog_apply_*.frag (shaders/include/fog_image_lookup.glsl).
#include <array>

#include "graph/execute/pass_execution.h"
#include "passes/fog/apply_draws.h"
#include "passes/fog/fog_passes.h"

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
    draws_.prepare(c, "fog_apply_transmittance.frag", "fog_apply_scattering.frag");
    const Extent size = c.desc("color").extent;
    const float frame[4] = {float(size.width), float(size.height), 0, 0};
    frame_ = c.device.create_buffer({"fog_apply frame", sizeof(frame), buffer_usage::uniform | buffer_usage::copy_dst});
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(frame)));
    SamplerDesc bilinear{"bilinear"};
    bilinear.filter = Filter::linear;
    bilinear_ = c.device.create_sampler(bilinear);
  }

  rhi::BindGroupId make_group(PassContext& c) {
    using rhi::BindGroupEntry;
    return c.device.create_bind_group({"fog_apply", draws_.layout(),
                                       {BindGroupEntry::of(0, c.view("fog_scattering")), BindGroupEntry::of(1, c.view("fog_transmittance")),
                                        BindGroupEntry::of(2, bilinear_), BindGroupEntry::of(3, frame_)}});
  }

  fog::ApplyDraws draws_;
  rhi::BufferId frame_;
  rhi::SamplerId bilinear_;
  std::array<rhi::BindGroupId, 2> groups_;
};

}  // namespace

PassDecl fog_apply_pass() {
  PassDecl d;
  d.name = "fog_apply";
  d.kind = PassKind::graphics;
  d.doc = "Applies a per-pixel fog technique's in-scattering and transmittance images to the scene's colour.";
  d.variants = {{"bilinear", "the images read bilinearly at each pixel's centre (upsamples a lower resolution)"}};
  d.slots = {
      slot_inout("color", ResourceKind::texture2d, Usage::color_attachment_load, "the scene's linear radiance"),
      slot_in("fog_scattering", ResourceKind::texture2d, Usage::sampled, "in-scattered radiance toward the camera, rgb"),
      slot_in("fog_transmittance", ResourceKind::texture2d, Usage::sampled, "transmittance from the camera to the surface, rgb"),
  };
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new FogApplyExecution()); };
  d.parity_bind_groups = true;
  return d;
}

}  // namespace volgraph
