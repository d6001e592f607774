// opacity_shadow_map (Kim & Neumann 2001, "Opacity shadow maps", kept as optical depth):
// volumetric shadows of the local media volumes for the light a shadow_map renders. Over
// that map's light view, `resolution`² columns (one per light ray) × `layers` layers from
// its near plane to its far plane — or, variant `deep` (deep opacity maps, Yuksel & Keyser
// 2008), from the column's first medium at a fixed spacing, so the layers spend their
// resolution inside the media; each texel holds the volumes' optical depth τ from the
// light to the layer's centre, marched once per column. froxel_scatter and scene read
// e^(−τ) with one trilinear lookup instead of marching through the volumes toward the
// light from every point they light; the global and height fog they take in closed form
// (shaders/include/light_transmittance.glsl), so the map leaves them out.
// The map depends on the scene's lights and media and on the light view alone (no
// jitter, no frame number): the pass is cached, and a frame whose cache key has not
// changed keeps last frame's map (PassDecl::cached).
// Shaders: shaders/opacity_shadow_map.comp, shaders/include/opacity_shadow.glsl.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/shadow_view.h"
#include "passes/uniform_mirrors.h"
#include "shaders/bindings/opacity_shadow_map.comp.h"

namespace volgraph {
namespace {

namespace opacity_shadow_map_shader = shaders::opacity_shadow_map_comp;

std::vector<ParamProblem> check_shadowed_media(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  return fog::media_fit_problems(scene, "shadowed");
}

struct OpacityShadowMapTable : PassTable {
  OpacityShadowMapTable()
      : PassTable("opacity_shadow_map", PassKind::compute,
                  "The local media volumes' optical depth from a shadow map's light, in layers over its light view (Kim & Neumann 2001).") {
    decl.needs = feature_bit(SceneFeature::medium);
    decl.check_scene = check_shadowed_media;
    // The shader reads the frame block's lights and media (not its camera or grid) and
    // the light view (whose key carries shadow_map's camera fit).
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::lights) | part_bit(ScenePart::media);
  }
  // Variants.
  VariantHandle layered =
      variant("layered", "`layers` evenly spaced layers along each light ray, from the view's near plane to its far plane");
  VariantHandle deep = variant("deep",
                               "deep opacity maps (Yuksel & Keyser 2008): `layers` layers `layer_spacing` apart along each light ray, "
                               "from where it first enters a media volume's shape; beyond the last, its τ");
  // Parameters.
  ParamHandle<int64_t> resolution = integer("resolution", 64, 8, 4096, "texels", "columns per side of the light view");
  ParamHandle<int64_t> layers = integer("layers", 32, 1, 512, "", "layers along each light ray");
  ParamHandle<int64_t> steps_per_layer = integer("steps_per_layer", 2, 1, 64, "", "march steps between two layers' centres");
  ParamHandle<int64_t> light_steps = integer("light_steps", 16, 0, 256, "",
                                             "march steps from the view's near plane back toward the light (media outside the view)");
  ParamHandle<double> distance = number("distance", 50, 0.01, 1e5, "m", "how far that march goes toward a directional light");
  ParamHandle<double> layer_spacing = number("layer_spacing", 0.25, 1e-4, 1e4, "m", "deep: the distance between two layers' centres");
  // Slots.
  SlotHandle light_view =
      input("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view (shadow_map.light_view)");
  SlotHandle optical_depth = output("optical_depth", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                                    SizeSpec::square_layers_of(resolution, layers),
                                    "τ rgb from the light to each layer's centre; a: where the column's layers lie (opacity_shadow.glsl)");
};

class OpacityShadowMapExecution final : public PassExecution {
 public:
  explicit OpacityShadowMapExecution(const OpacityShadowMapTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "opacity_shadow_map.comp");
    // The frame block is written when the pass runs, the view by shadow_map: checked once.
    plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(program_, 0, 0, s.name() + " frame");
    plumbing::check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(program_, 0, 1, s.name() + " light_view");
    frame_ = s.device.create_buffer({s.name() + " frame", sizeof(gpu::FogFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    const gpu::OpacityParams params{{int32_t(s.param(t_.steps_per_layer)), int32_t(s.param(t_.light_steps)), s.variant_is(t_.deep) ? 1 : 0, 0},
                                    {float(s.param(t_.distance)), float(s.param(t_.layer_spacing)), 0, 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, opacity_shadow_map_shader::params, s.name() + " params", params);
  }

  // Runs when the cache key changed (the first frame, or new lights, media or light
  // view): the frame block is packed from the scene as it is now.
  void record(PassContext& c) override {
    fog::FogFrameInputs frame_inputs;  // the lights and media; no froxel grid
    frame_inputs.range = {c.scene->camera.near, c.scene->camera.far, physics::FroxelDistribution::linear};
    frame_inputs.jitter = false;
    const gpu::FogFrame frame = fog::make_fog_frame(c, 0, frame_inputs, lighting_);  // frame 0: the map is frame invariant
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    const rhi::BindGroupId group = c.bind_group(program_, {bind(opacity_shadow_map_shader::frame, frame_), bind(opacity_shadow_map_shader::shadow, c.buffer(t_.light_view)),
                                                           bind(opacity_shadow_map_shader::optical_depth, c.view(t_.optical_depth)), bind(opacity_shadow_map_shader::params, params_)});
    const Extent size = c.extent(t_.optical_depth);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, {size.width, size.height, 1});  // a column each
  }

 private:
  const OpacityShadowMapTable& t_;
  plumbing::ComputeProgram program_;
  plumbing::SceneLighting lighting_;
  rhi::BufferId frame_, params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(OpacityShadowMapTable, OpacityShadowMapExecution);

}  // namespace volgraph
