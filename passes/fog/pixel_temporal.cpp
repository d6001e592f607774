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
// shaders/include/view_rays.glsl `view_uvz` ↔ physics/camera.h.
#include "graph/execute/pass_execution.h"
#include "passes/register_pass.h"
#include "passes/fog/temporal.h"
#include "shaders/bindings/pixel_temporal.comp.h"

namespace volgraph {
namespace {

namespace pixel_temporal_shader = shaders::pixel_temporal_comp;

struct PixelTemporalTable : fog::TemporalTable {
  PixelTemporalTable()
      : TemporalTable("pixel_temporal",
                      "Temporal accumulation of a per-pixel fog technique's images: reprojected by the scene's depth, blended with this frame's.") {
    // It averages cloud_march's jitter too, so a scene with clouds and no medium keeps it.
    decl.needs = 0;
    decl.needs_any = feature_bit(SceneFeature::medium) | feature_bit(SceneFeature::clouds);
  }
  VariantHandle reprojected =
      variant("reprojected", "the last frame's results read bilinearly where the last frame's camera saw each texel's point");
  // Slots (the parameters are TemporalTable's).
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (d32; 1 where nothing was drawn)",
                           {.format = Format::d32_float});
  SlotHandle fog_scattering = input("fog_scattering", ResourceKind::texture2d, Usage::sampled, "this frame's in-scattered radiance, rgb");
  SlotHandle fog_transmittance = input("fog_transmittance", ResourceKind::texture2d, Usage::sampled, "this frame's transmittance, rgb");
  SlotHandle scattering = output_like("scattering", fog_scattering, Usage::storage_write,
                                      "in-scattered radiance blended over frames, rgb; a: frames");
  SlotHandle transmittance =
      output_like("transmittance", fog_transmittance, Usage::storage_write,
                  "transmittance blended over frames, rgb; a: the texel's view depth (m), to find disocclusions next frame");
  SlotHandle scattering_history = history("scattering_history", scattering, "the last frame's blended in-scattering");
  SlotHandle transmittance_history = history("transmittance_history", transmittance, "the last frame's blended transmittance");
};

class PixelTemporalExecution final : public fog::TemporalExecution {
 public:
  explicit PixelTemporalExecution(const PixelTemporalTable& table)
      : TemporalExecution(table, "pixel_temporal.comp", table.scattering, pixel_temporal_shader::params.binding), t_(table) {}

 private:
  void setup_blocks(PassSetup& s) override {
    frame_ = s.device.create_buffer({"pixel_temporal frame", sizeof(gpu::FogFrame),
                                     rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  // This frame's camera, as a frame block (its grid is unused).
  void write_blocks(PassContext& c) override {
    fog::FogFrameInputs in;
    in.grid = c.extent(t_.scattering);
    in.range = {c.scene->camera.near, c.scene->camera.far, physics::FroxelDistribution::linear};
    in.jitter = false;
    const gpu::FogFrame frame = fog::make_fog_frame(c, c.frame, in, lighting_);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
  }

  std::vector<rhi::BoundResource> entries(PassContext& c) override {
    return {bind(pixel_temporal_shader::frame, frame_),
            bind(pixel_temporal_shader::scene_depth, c.view(t_.depth)),
            bind(pixel_temporal_shader::fog_scattering, c.view(t_.fog_scattering)),
            bind(pixel_temporal_shader::fog_transmittance, c.view(t_.fog_transmittance)),
            bind(pixel_temporal_shader::scattering_history, c.view(t_.scattering_history)),
            bind(pixel_temporal_shader::transmittance_history, c.view(t_.transmittance_history)),
            bind(pixel_temporal_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
            bind(pixel_temporal_shader::bilinear, c.sampler(rhi::StockSampler::linear_clamp)),
            bind(pixel_temporal_shader::accumulated_scattering, c.view(t_.scattering)),
            bind(pixel_temporal_shader::accumulated_transmittance, c.view(t_.transmittance)),
            bind(pixel_temporal_shader::params, params())};
  }

  const PixelTemporalTable& t_;
  rhi::BufferId frame_;
  plumbing::SceneLighting lighting_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(PixelTemporalTable, PixelTemporalExecution);

}  // namespace volgraph
