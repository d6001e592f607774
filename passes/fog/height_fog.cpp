// height_fog: exponential height fog in closed form along each pixel's ray, from the
// scene's `media.height_fog` (σ(y) = σ_base·e^(−falloff·(y − base_height))). The
// transmittance is e^(−τ) with τ the closed-form optical depth (media.glsl
// height_fog_optical_depth). A directional light reaches each point dimmed by the fog
// between it and the light, as the reference has it: τ_sun(y) = σt_base·e^(−falloff·(y −
// base))/(falloff·ω_y) (light_transmittance.glsl, the fog above the point along ω toward
// the light; no light for ω_y ≤ 0). Along the ray τ_view + τ_sun is linear in the ray's
// unit-density optical depth Δ, so the in-scattering integrates exactly:
//   L_sun = σs·p_HG(θ)·E·Δ·e^(−a)·(1 − e^(−x))/x  (media.glsl attenuated_length_from),
// a the sun's optical depth at the camera, a + x the view's plus the sun's at the ray's end.
// Ambient and emission, proportional to the density, integrate to
// (σs·L_ambient + emission)·(1 − T)/σt (σt_base → 0 handled by attenuated_length).
// The approximation: only directional lights count (point and spot lights add nothing:
// use analytic_fog or a march), and nothing casts a shadow. Exact when those hold. Other
// media of the scene are ignored; pixels hitting nothing integrate to the camera's far
// plane. Shader: shaders/height_fog.comp.
#include "graph/scene/scene.h"
#include "passes/register_pass.h"
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
                      "Exponential height fog in closed form per pixel: exact transmittance, in-scattering of directional lights dimmed by the fog toward them.") {
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

VOLGRAPH_REGISTER_PASS(HeightFogTable, HeightFogExecution);

}  // namespace volgraph
