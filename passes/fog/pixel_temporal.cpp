// pixel_temporal: temporal accumulation of a per-pixel fog technique's two images
// (raymarch_fog's jittered steps, or any technique with fog_apply's contract). Per texel
// of the images, its point — the scene's depth there, the far plane where nothing was
// drawn — is reprojected by the last frame's camera; the last frame's results are read
// there bilinearly and blended with this frame's — a moving average whose first frames
// count equally (shaders/include/temporal_blend.glsl) — unless the last frame saw
// something else there (a disocclusion: the view depth kept with the history differs by
// more than 5 %), where this frame's values start afresh. The results go to fog_apply and
// are kept as the next frame's histories (two history pairs). On the first frame they
// are this frame's images, unchanged. Shader: shaders/pixel_temporal.comp; reprojection:
// shaders/include/view_rays.glsl `view_uvz` ↔ passes/shading/camera.h.
#include "graph/execute/pass_execution.h"
#include "passes/fog/fog_passes.h"
#include "passes/fog/temporal.h"

namespace volgraph {
namespace {

class PixelTemporalExecution final : public fog::TemporalExecution {
 public:
  PixelTemporalExecution() : TemporalExecution("pixel_temporal.comp", "scattering") {}

 private:
  // This frame's camera, as a frame block (its grid is unused).
  void write_blocks(PassContext& c) override {
    if (!frame_) {
      frame_ = c.device.create_buffer({"pixel_temporal frame", sizeof(fog::GpuFogFrame),
                                       rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    }
    fog::FogFrameInputs in;
    in.grid = c.desc("scattering").extent;
    in.range = {c.scene->camera.near, c.scene->camera.far, shading::FroxelDistribution::linear};
    in.jitter = false;
    const fog::GpuFogFrame frame = fog::make_fog_frame(c, in);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
  }

  std::vector<rhi::BindGroupEntry> entries(PassContext& c) override {
    using rhi::BindGroupEntry;
    return {BindGroupEntry::of(0, frame_),
            BindGroupEntry::of(1, c.view("depth")),
            BindGroupEntry::of(2, c.view("fog_scattering")),
            BindGroupEntry::of(3, c.view("fog_transmittance")),
            BindGroupEntry::of(4, c.view("scattering_history")),
            BindGroupEntry::of(5, c.view("transmittance_history")),
            BindGroupEntry::of(6, nearest()),
            BindGroupEntry::of(7, linear()),
            BindGroupEntry::of(8, c.view("scattering")),
            BindGroupEntry::of(9, c.view("transmittance")),
            BindGroupEntry::of(10, params())};
  }

  rhi::BufferId frame_;
};

}  // namespace

PassDecl pixel_temporal_pass() {
  PassDecl d;
  d.name = "pixel_temporal";
  d.kind = PassKind::compute;
  d.doc = "Temporal accumulation of a per-pixel fog technique's images: reprojected by the scene's depth, blended with this frame's.";
  d.variants = {{"reprojected", "the last frame's results read bilinearly where the last frame's camera saw each texel's point"}};
  d.params = fog::temporal_params();
  SlotDecl depth = slot_in("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (d32; 1 where nothing was drawn)");
  depth.format = Format::d32_float;
  d.slots = {
      depth,
      slot_in("fog_scattering", ResourceKind::texture2d, Usage::sampled, "this frame's in-scattered radiance, rgb"),
      slot_in("fog_transmittance", ResourceKind::texture2d, Usage::sampled, "this frame's transmittance, rgb"),
      slot_out_like("scattering", "fog_scattering", Usage::storage_write, "in-scattered radiance blended over frames, rgb; a: frames"),
      slot_out_like("transmittance", "fog_transmittance", Usage::storage_write,
                    "transmittance blended over frames, rgb; a: the texel's view depth (m), to find disocclusions next frame"),
      slot_history("scattering_history", "scattering", "the last frame's blended in-scattering"),
      slot_history("transmittance_history", "transmittance", "the last frame's blended transmittance"),
  };
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new PixelTemporalExecution()); };
  d.parity_bind_groups = true;
  return d;
}

}  // namespace volgraph
