// analytic_fog: single scattering in the scene's global homogeneous fog, without shadows,
// per pixel in closed form or by a short fixed quadrature:
// - point lights: the airlight of Sun, Ramamoorthi, Narasimhan, Nayar 2005 with extinction
//   and HG phase, σs·I·A (shaders/include/airlight.glsl ↔ physics/airlight.h:
//   composite Gauss–Legendre, relative error ≤ 3e-5 in float where measured; the ray's
//   distance to the light is clamped to 1e-4 m, so a light on the ray stays finite);
// - spot lights: the same integrand with the cone's falloff, the ray cut where it crosses
//   the inner and outer cones and each lit piece by Gauss–Legendre in the airlight's
//   variable (light_volume's unshadowed I(t): shaders/include/light_volume_integral.glsl ↔
//   physics/light_volume_integral.h, its error measured there);
// - directional lights: constant along the ray, σs·p_HG(θ)·E·(1 − e^(−σt·D))/σt;
// - emission and ambient likewise: (emission + σs·L_ambient)·(1 − e^(−σt·D))/σt;
// transmittance e^(−σt·D). D is the distance along the ray to the surface, or to the far
// plane where nothing was drawn. Height fog and volumes are ignored (height_fog,
// the froxel chain). Shader: shaders/analytic_fog.comp.
#include "graph/scene/scene.h"
#include "passes/register_pass.h"
#include "passes/fog/pixel_fog.h"

namespace volgraph {
namespace {

std::vector<ParamProblem> check_global_fog(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  if (scene.media.fog) return {};
  return {{"", "analytic_fog renders the scene's global media.fog, and the scene has none"}};
}

struct AnalyticFogTable : fog::PixelFogTable {
  AnalyticFogTable()
      : PixelFogTable("analytic_fog",
                      "Single scattering of point, spot and directional lights in homogeneous global fog, unshadowed (Sun et al. 2005 airlight).") {
    decl.check_scene = check_global_fog;
  }
  VariantHandle airlight =
      variant("airlight", "point and spot lights by the airlight integral with extinction (spots cut at their cones); directional lights in closed form");
  ParamHandle<std::array<double, 3>> ambient = vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the fog scatters");
};

class AnalyticFogExecution final : public fog::PixelFogExecution {
 public:
  explicit AnalyticFogExecution(const AnalyticFogTable& t)
      : PixelFogExecution(t, "analytic_fog.comp", [&t](const PassSetup& s) { return fog::PixelFogInputs{.ambient = s.param(t.ambient)}; }) {}
};

}  // namespace

VOLGRAPH_REGISTER_PASS(AnalyticFogTable, AnalyticFogExecution);

}  // namespace volgraph
