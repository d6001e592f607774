// Opaque scene: Lambertian surfaces lit by the scene's lights (DESIGN.md units:
// ρ/π · E · cos θ · V), emissive surfaces and the background radiance.
#include "passes/passes.h"

namespace volgraph {

PassDecl scene_pass() {
  PassDecl d;
  d.name = "scene";
  d.kind = PassKind::graphics;
  d.doc = "Opaque surfaces, lit and shadowed, over the background; linear radiance and depth.";
  d.variants = {{"lambert", "Lambertian reflection of every light, shadowed by the shadow map when wired"}};
  d.params = {
      param_vec3("ambient", {0, 0, 0}, 0, 1e6, "W/m²", "uniform irradiance added to every surface (unshadowed)"),
      param_bool("shadows", true, "sample the shadow map when one is wired"),
  };
  SlotDecl color = slot_out("color", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float,
                            SizeSpec::of_output(), "linear radiance");
  color.format_overridable = true;
  color.size_overridable = true;
  d.slots = {
      slot_optional_in("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map"),
      slot_optional_in("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view"),
      color,
      slot_out("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float, SizeSpec::of_output(),
               "scene depth, for later passes (fog, translucency)"),
  };
  d.slots[0].format = Format::d32_float;
  return d;
}

}  // namespace volgraph
