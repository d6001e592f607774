// Shadow map: depth from one light's view. Directional lights use an orthographic
// projection fitted to the camera frustum's bounds; spot lights a perspective one
// spanning the outer cone.
#include "graph/scene/scene.h"
#include "passes/passes.h"

namespace volgraph {
namespace {

// The light must exist, be directional or spot, and cast shadows.
std::vector<ParamProblem> check_light(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params) {
  const int64_t index = std::get<int64_t>(params[size_t(decl.param_index("light"))]);
  if (index >= int64_t(scene.lights.size())) {
    return {{"light", "light " + std::to_string(index) + " does not exist: scene.lights has " +
                          std::to_string(scene.lights.size())}};
  }
  const Light& light = scene.lights[size_t(index)];
  if (light.type == LightType::point) {
    return {{"light", "light " + std::to_string(index) + " is a point light; shadow_map takes a directional or spot light"}};
  }
  if (!light.cast_shadows) return {{"light", "light " + std::to_string(index) + " has cast_shadows: false"}};
  return {};
}

}  // namespace

PassDecl shadow_map_pass() {
  PassDecl d;
  d.name = "shadow_map";
  d.kind = PassKind::graphics;
  d.doc = "Depth of the scene seen from a directional (fitted orthographic) or spot (perspective) light.";
  d.variants = {
      {"pcf", "percentage-closer filtering over a Poisson disc of pcf_radius texels"},
      {"hard", "one depth comparison per lookup"},
  };
  d.params = {
      param_int("light", 0, 0, 63, "", "index of the light in scene.lights (directional or spot)"),
      param_int("resolution", 2048, 64, 16384, "texels", "side of the square shadow map"),
      param_number("depth_bias", 0.002, 0, 0.1, "", "constant bias, in the light's normalised depth"),
      param_number("slope_bias", 1.5, 0, 16, "", "bias scaled by the surface slope seen from the light"),
      param_number("pcf_radius", 1.5, 0, 16, "texels", "filter radius of the pcf variant"),
  };
  d.slots = {
      slot_out("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float,
               SizeSpec::square_of("resolution"), "light-space depth"),
      slot_out("light_view", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(256),
               "the light's view-projection matrix and bias, for passes that sample `depth`"),
  };
  d.needs = feature_bit(SceneFeature::shadow_casting_light);
  d.check_scene = check_light;
  return d;
}

}  // namespace volgraph
