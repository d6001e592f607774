// fog_apply: a per-pixel fog technique's result on the scene's colour, L = T·L_surface +
// L_scat, from the two images the technique wrote (in-scattered radiance and
// transmittance, at the frame's resolution or lower: read bilinearly at each pixel, or —
// variant depth_aware, which needs the scene's depth wired — by joint bilateral upsampling).
// Shaders: shaders/fog_apply_*.frag (shaders/include/fog_image_lookup*.glsl).
#include <array>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/apply_draws.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "shaders/bindings/fog_apply_transmittance.frag.h"
#include "shaders/bindings/fog_apply_transmittance_depth_aware.frag.h"

namespace volgraph {
namespace {

namespace fog_apply_transmittance_shader = shaders::fog_apply_transmittance_frag;
namespace fog_apply_transmittance_depth_aware_shader = shaders::fog_apply_transmittance_depth_aware_frag;

struct FogApplyTable : PassTable {
  FogApplyTable()
      : PassTable("fog_apply", PassKind::graphics,
                  "Applies a per-pixel fog technique's in-scattering and transmittance images to the scene's colour.") {
    // It composites cloud_march's images too, so a scene with clouds and no medium keeps it.
    decl.needs_any = feature_bit(SceneFeature::medium) | feature_bit(SceneFeature::clouds);
  }
  // Variants: how the images are read at each pixel (the first is the default).
  VariantHandle bilinear = variant("bilinear", "the images read bilinearly at each pixel's centre (upsamples a lower resolution)");
  VariantHandle depth_aware =
      variant("depth_aware", "joint bilateral upsampling (Kopf et al. 2007) guided by the scene's `depth`");
  // Slots.
  SlotHandle color = inout("color", ResourceKind::texture2d, Usage::color_attachment_load, "the scene's linear radiance");
  SlotHandle fog_scattering =
      input("fog_scattering", ResourceKind::texture2d, Usage::sampled, "in-scattered radiance toward the camera, rgb");
  SlotHandle fog_transmittance =
      input("fog_transmittance", ResourceKind::texture2d, Usage::sampled, "transmittance from the camera to the surface, rgb");
  SlotHandle depth = optional_input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth, for depth_aware",
                                    {.format = Format::d32_float, .required_in = {depth_aware}});
};

class FogApplyExecution final : public PassExecution {
 public:
  explicit FogApplyExecution(const FogApplyTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    depth_aware_ = s.variant_is(t_.depth_aware);  // the loader made sure `depth` is wired
    if (depth_aware_) {
      draws_.prepare(s, t_.color, "fog_apply_transmittance_depth_aware.frag", "fog_apply_scattering_depth_aware.frag");
    } else {
      draws_.prepare(s, t_.color, "fog_apply_transmittance.frag", "fog_apply_scattering.frag");
    }
    const Extent size = s.extent(t_.color);
    const Camera& camera = s.scene->camera;
    const gpu::FogApplyFrame frame{{float(size.width), float(size.height), float(camera.near), float(camera.far)}};
    for (const plumbing::RenderProgram* p : draws_.programs()) {
      plumbing::check_wrapped_uniform_mirror<gpu::FogApplyFrame>(*p, fog_apply_transmittance_shader::frame, s.name() + " frame");
    }
    frame_ = plumbing::create_uniform_block(s.device, s.name() + " frame", frame);
  }

  // The images may be history pairs' (pixel_temporal): the cache gives each object its group.
  void record(PassContext& c) override {
    if (depth_aware_) {
      namespace shader = fog_apply_transmittance_depth_aware_shader;
      draws_.record(c, c.bind_group(draws_.program(), {bind(shader::fog_scattering, c.view(t_.fog_scattering)),
                                                       bind(shader::fog_transmittance, c.view(t_.fog_transmittance)),
                                                       bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                                                       bind(shader::frame, frame_), bind(shader::scene_depth, c.view(t_.depth))}));
    } else {
      namespace shader = fog_apply_transmittance_shader;
      draws_.record(c, c.bind_group(draws_.program(), {bind(shader::fog_scattering, c.view(t_.fog_scattering)),
                                                       bind(shader::fog_transmittance, c.view(t_.fog_transmittance)),
                                                       bind(shader::bilinear, c.sampler(rhi::StockSampler::linear_clamp)),
                                                       bind(shader::frame, frame_)}));
    }
  }

 private:
  const FogApplyTable& t_;
  fog::ApplyDraws draws_;
  bool depth_aware_ = false;
  rhi::BufferId frame_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(FogApplyTable, FogApplyExecution);

}  // namespace volgraph
