// opacity_shadow_map (Kim & Neumann 2001, "Opacity shadow maps", kept as optical depth):
// volumetric shadows of the media for the light a shadow_map renders. Over that map's
// light view, `resolution`² columns (one per light ray) × `layers` layers from its near
// plane to its far plane; each texel holds the optical depth τ from the light to the
// layer's centre, marched once per column. froxel_scatter and scene read e^(−τ) with one
// trilinear lookup instead of marching toward the light from every point they light.
// Shaders: shaders/opacity_shadow_map.comp, shaders/include/opacity_shadow.glsl.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/fog/fog_passes.h"
#include "passes/shading/programs.h"

namespace volgraph {
namespace {

struct GpuOpacityParams {
  int32_t steps[4];   // x per layer, y toward the light from the column's start
  float distances[4];  // x the march toward a directional light (m)
};

class OpacityShadowMapExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    const Extent size = c.desc("optical_depth").extent;
    shading::dispatch(c.encoder, c.graph_pass().name, program_, {group_}, {size.width, size.height, 1});  // a column each
  }

 private:
  void prepare(PassContext& c) {
    using rhi::BindGroupEntry;
    program_ = shading::create_compute_program(c.device, "opacity_shadow_map.comp");
    fog::FogFrameInputs frame_inputs;  // the lights and media; no froxel grid
    frame_inputs.range = {c.scene->camera.near, c.scene->camera.far, shading::FroxelDistribution::linear};
    frame_inputs.jitter = false;
    const GpuOpacityParams params{{int32_t(std::get<int64_t>(c.param("steps_per_layer"))),
                                   int32_t(std::get<int64_t>(c.param("light_steps"))), 0, 0},
                                  {float(std::get<double>(c.param("distance"))), 0, 0, 0}};
    const std::string& name = c.graph_pass().name;
    group_ = c.device.create_bind_group(
        {name, program_.layouts[0],
         {BindGroupEntry::of(0, shading::create_uniform_block(c.device, name + " frame", fog::make_fog_frame(c, frame_inputs))),
          BindGroupEntry::of(1, c.buffer("light_view")), BindGroupEntry::of(2, c.view("optical_depth")),
          BindGroupEntry::of(3, shading::create_uniform_block(c.device, name + " params", params))}});
  }

  shading::ComputeProgram program_;
  rhi::BindGroupId group_;
};

std::vector<ParamProblem> check_media(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  return fog::media_fit_problems(scene, "shadowed");
}

}  // namespace

PassDecl opacity_shadow_map_pass() {
  PassDecl d;
  d.name = "opacity_shadow_map";
  d.kind = PassKind::compute;
  d.doc = "The media's optical depth from a shadow map's light, in layers over its light view (Kim & Neumann 2001).";
  d.variants = {{"layered", "`layers` evenly spaced layers along each light ray, from the view's near plane to its far plane"}};
  d.params = {
      param_int("resolution", 64, 8, 4096, "texels", "columns per side of the light view"),
      param_int("layers", 32, 1, 512, "", "layers along each light ray"),
      param_int("steps_per_layer", 2, 1, 64, "", "march steps between two layers' centres"),
      param_int("light_steps", 16, 0, 256, "",
                "march steps from the view's near plane back toward the light (media outside the view)"),
      param_number("distance", 50, 0.01, 1e5, "m", "how far that march goes toward a directional light"),
  };
  d.slots = {
      slot_in("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view (shadow_map.light_view)"),
      slot_out("optical_depth", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
               SizeSpec::square_layers_of("resolution", "layers"), "τ rgb from the light to each layer's centre"),
  };
  d.needs = feature_bit(SceneFeature::medium);
  d.check_scene = check_media;
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new OpacityShadowMapExecution()); };
  return d;
}

}  // namespace volgraph
