// depth_fog (the eq. 14.12–14.14): the classic fog factor f of the distance z to
// each pixel's surface — linear between `start` and `end`, exponential e^(−density·z), or
// exponential squared e^(−(density·z)²) — as the transmittance, and (1 − f)·`color` as the
// in-scattered radiance. z is measured along the pixel's ray from the camera (not view
// depth), to the far plane where nothing was drawn. Not physically based: the fog has one
// colour and ignores the scene's media and lights (it still needs a medium to run).
// Shader: shaders/depth_fog.comp (f from shaders/include/media.glsl).
#include "passes/fog/fog_passes.h"
#include "passes/fog/pixel_fog.h"

namespace volgraph {
namespace {

int32_t variant_code(std::string_view variant) {
  if (variant == "linear") return 0;
  if (variant == "exponential_squared") return 2;
  return 1;  // exponential
}

// The shader's Params block.
fog::PixelFogInputs depth_fog_inputs(const PassContext& c) {
  const auto color = std::get<std::array<double, 3>>(c.param("color"));
  const float params[8] = {float(std::get<double>(c.param("start"))), float(std::get<double>(c.param("end"))),
                           float(std::get<double>(c.param("density"))), float(variant_code(c.variant())),
                           float(color[0]), float(color[1]), float(color[2]), 0};
  const auto bytes = std::as_bytes(std::span(params));
  return {{bytes.begin(), bytes.end()}, {0, 0, 0}};
}

}  // namespace

PassDecl depth_fog_pass() {
  PassDecl d;
  d.name = "depth_fog";
  d.kind = PassKind::compute;
  d.doc = "Classic depth fog (eq. 14.12–14.14): fog factor f of the distance along each pixel's ray as transmittance, (1 − f)·color in-scattered.";
  d.variants = {
      {"exponential", "f = e^(−density·z) (eq. 14.13)"},
      {"linear", "f = (end − z)/(end − start), clamped to [0, 1] (eq. 14.12)"},
      {"exponential_squared", "f = e^(−(density·z)²) (eq. 14.14)"},
  };
  d.params = {
      param_number("start", 5, 0, 1e6, "m", "linear: where the fog begins"),
      param_number("end", 50, 0, 1e6, "m", "linear: where the fog hides everything"),
      param_number("density", 0.05, 0, 1e4, "1/m", "exponential, exponential_squared: the fog's density"),
      param_vec3("color", {0.5, 0.55, 0.6}, 0, 1e6, "W/(m²·sr)", "the fog's radiance, which replaces what it hides"),
  };
  d.slots = fog::pixel_fog_slots();
  d.needs = feature_bit(SceneFeature::medium);
  d.make_execution = fog::pixel_fog_execution("depth_fog.comp", depth_fog_inputs);
  return d;
}

}  // namespace volgraph
