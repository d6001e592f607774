// height_fog: exponential height fog in closed form along each pixel's ray, from the
// scene's `media.height_fog` (σ(y) = σ_base·e^(−falloff·(y − base_height))). The
// transmittance is e^(−τ) with τ the closed-form optical depth (media.glsl
// height_fog_optical_depth). Every source proportional to the density — σs·p(θ)·E of a
// directional light, σs·L_ambient, emission — integrates exactly to
// source_base/σt_base·(1 − T) (with σt_base → 0 handled by attenuated_length):
//   L_scat = (σs·(Σ_directional p_HG(θ)·E + L_ambient) + emission)·(1 − T)/σt.
// The approximation: lighting unshadowed and constant along the ray, so only directional
// lights count (point and spot lights add nothing: use analytic_fog), nothing casts a
// shadow, and the sun's light is not dimmed by the fog above the point (the reference
// dims it). Exact when those hold. Other media of the scene are ignored; pixels hitting
// nothing integrate to the camera's far plane. Shader: shaders/height_fog.comp.
#include "graph/scene/scene.h"
#include "passes/fog/fog_passes.h"
#include "passes/fog/pixel_fog.h"

namespace volgraph {
namespace {

std::vector<ParamProblem> check_height_fog(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  if (scene.media.height_fog) return {};
  return {{"", "height_fog renders the scene's media.height_fog, and the scene has none"}};
}

struct HeightFogTable : fog::PixelFogTable {
  HeightFogTable()
      : PixelFogTable("height_fog",
                      "Exponential height fog in closed form per pixel: exact transmittance, in-scattering of unshadowed directional lights.") {
    decl.check_scene = check_height_fog;
  }
  VariantHandle closed_form = variant("closed_form", "optical depth and in-scattering integrated analytically along each pixel's ray");
  ParamHandle<std::array<double, 3>> ambient = vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the fog scatters");
};

class HeightFogExecution final : public fog::PixelFogExecution {
 public:
  explicit HeightFogExecution(const HeightFogTable& t)
      : PixelFogExecution(t, "height_fog.comp", [&t](const PassSetup& s) { return fog::PixelFogInputs{.ambient = s.param(t.ambient)}; }) {}
};

}  // namespace

PassDecl height_fog_pass() { return pass_type<HeightFogTable, HeightFogExecution>(); }

}  // namespace volgraph
