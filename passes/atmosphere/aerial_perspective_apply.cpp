// aerial_perspective_apply: the air between the camera and every surface it sees, applied
// to the scene's colour after the fog's own apply pass — L = T_air·L + S_air·E, the air
// counted in front of the fog (the fog lies within a few hundred metres of the camera,
// the air over kilometres), so the fog's in-scattering and transmittance are attenuated
// and added to by the air before it. T_air and S_air are atmosphere_aerial_perspective's
// volumes read at the pixel and its surface's distance (one function for every technique:
// shaders/include/atmosphere_aerial_lookup.glsl); sky pixels (depth at the far plane)
// already hold their whole ray's air and are left alone. Two full-screen draws, as the
// fog's apply passes: the first multiplies by T_air, the second adds S_air·E.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/register_pass.h"
#include "passes/fog/apply_draws.h"
#include "passes/uniform_mirrors.h"
#include "shaders/bindings/aerial_perspective_apply_transmittance.frag.h"

namespace volgraph {
namespace {

// Both draws' shaders declare include/aerial_apply.glsl's bindings.
namespace aerial_perspective_apply_transmittance_shader = shaders::aerial_perspective_apply_transmittance_frag;

struct AerialPerspectiveApplyTable : PassTable {
  AerialPerspectiveApplyTable()
      : PassTable("aerial_perspective_apply", PassKind::graphics,
                  "Applies the atmosphere's aerial perspective to the scene's surfaces: L = T_air·L + S_air·E at each pixel's depth.") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
  }
  // Variants.
  VariantHandle trilinear = variant("trilinear", "one trilinear lookup of the aerial-perspective volumes per pixel at its surface's distance");
  // Slots.
  SlotHandle color = inout("color", ResourceKind::texture2d, Usage::color_attachment_load, "the scene's linear radiance");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth", {.format = Format::d32_float});
  SlotHandle aerial_scattering = input("aerial_scattering", ResourceKind::texture3d, Usage::sampled,
                                       "the air's in-scattering per unit E (atmosphere_aerial_perspective.aerial_scattering)");
  SlotHandle aerial_transmittance = input("aerial_transmittance", ResourceKind::texture3d, Usage::sampled,
                                          "the air's transmittance (atmosphere_aerial_perspective.aerial_transmittance)");
  SlotHandle lookup = input("lookup", ResourceKind::buffer, Usage::uniform_read, "the volumes' frame (atmosphere_aerial_perspective.lookup)");
};

class AerialPerspectiveApplyExecution final : public PassExecution {
 public:
  explicit AerialPerspectiveApplyExecution(const AerialPerspectiveApplyTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    draws_.prepare(s, t_.color, "aerial_perspective_apply_transmittance.frag", "aerial_perspective_apply_scattering.frag");
    for (const plumbing::RenderProgram* p : draws_.programs()) {
      plumbing::check_wrapped_uniform_mirror<gpu::AerialLookup>(*p, 0, 0, s.name() + " lookup");
    }
  }

  void record(PassContext& c) override {
    const rhi::BindGroupId group = c.bind_group(
        draws_.program(),
        {bind(aerial_perspective_apply_transmittance_shader::lookup, c.buffer(t_.lookup)), bind(aerial_perspective_apply_transmittance_shader::scene_depth, c.view(t_.depth)),
         bind(aerial_perspective_apply_transmittance_shader::aerial_scattering, c.view(t_.aerial_scattering)), bind(aerial_perspective_apply_transmittance_shader::aerial_transmittance, c.view(t_.aerial_transmittance)),
         bind(aerial_perspective_apply_transmittance_shader::trilinear, c.sampler(rhi::StockSampler::trilinear_clamp)), bind(aerial_perspective_apply_transmittance_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))});
    draws_.record(c, group);
  }

 private:
  const AerialPerspectiveApplyTable& t_;
  fog::ApplyDraws draws_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(AerialPerspectiveApplyTable, AerialPerspectiveApplyExecution);

}  // namespace volgraph
