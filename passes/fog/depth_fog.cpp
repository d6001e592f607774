// depth_fog (RTR4 eq. 14.12–14.14): the classic fog factor f of the distance z to
// each pixel's surface — linear between `start` and `end`, exponential e^(−density·z), or
// exponential squared e^(−(density·z)²) — as the transmittance, and (1 − f)·`color` as the
// in-scattered radiance. z is measured along the pixel's ray from the camera (not view
// depth), to the far plane where nothing was drawn. Not physically based: the fog has one
// colour and ignores the scene's media and lights (it still needs a medium to run).
// Shader: shaders/depth_fog.comp (f from shaders/include/media.glsl).
#include "passes/register_pass.h"
#include "shaders/bindings/depth_fog.comp.h"  // gpu::DepthFogParams, its layout asserted
#include "passes/fog/pixel_fog.h"
#include "passes/uniform_mirrors.h"
#include "shaders/include/depth_fog_codes.h"

namespace volgraph {
namespace {

struct DepthFogTable : fog::PixelFogTable {
  DepthFogTable()
      : PixelFogTable("depth_fog",
                      "Classic depth fog (eq. 14.12–14.14): fog factor f of the distance along each pixel's ray as transmittance, (1 − f)·color in-scattered.") {}
  // Variants: the fog factor (the first is the default).
  VariantHandle exponential = variant("exponential", "f = e^(−density·z) (eq. 14.13)", DEPTH_FOG_EXPONENTIAL);
  VariantHandle linear = variant("linear", "f = (end − z)/(end − start), clamped to [0, 1] (eq. 14.12)", DEPTH_FOG_LINEAR);
  VariantHandle exponential_squared =
      variant("exponential_squared", "f = e^(−(density·z)²) (eq. 14.14)", DEPTH_FOG_EXPONENTIAL_SQUARED);
  // Parameters (the slots are PixelFogTable's).
  ParamHandle<double> start = number("start", 5, 0, 1e6, "m", "linear: where the fog begins");
  ParamHandle<double> end = number("end", 50, 0, 1e6, "m", "linear: where the fog hides everything");
  ParamHandle<double> density = number("density", 0.05, 0, 1e4, "1/m", "exponential, exponential_squared: the fog's density");
  ParamHandle<std::array<double, 3>> color =
      vec3("color", {0.5, 0.55, 0.6}, 0, 1e6, "W/(m²·sr)", "the fog's radiance, which replaces what it hides");
};

// The shader's Params block.
fog::PixelFogInputs depth_fog_inputs(const DepthFogTable& t, const PassSetup& s) {
  const std::array<double, 3>& color = s.param(t.color);
  const gpu::DepthFogParams params{
      {float(s.param(t.start)), float(s.param(t.end)), float(s.param(t.density)), float(s.variant().shader_code)},
      {float(color[0]), float(color[1]), float(color[2]), 0}};
  return fog::PixelFogInputs::with_params(params, {0, 0, 0});
}

class DepthFogExecution final : public fog::PixelFogExecution {
 public:
  explicit DepthFogExecution(const DepthFogTable& t)
      : PixelFogExecution(t, "depth_fog.comp", [&t](const PassSetup& s) { return depth_fog_inputs(t, s); }) {}
};

}  // namespace

VOLGRAPH_REGISTER_PASS(DepthFogTable, DepthFogExecution);

}  // namespace volgraph
