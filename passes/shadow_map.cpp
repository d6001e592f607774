// Shadow map: depth of the scene from one light. A directional light gets an orthographic
// window fitted to the shadow receivers the camera sees (its frustum up to `distance`,
// clipped to the scene's bounds), snapped to whole texels, with its depth range over the
// whole scene so that every caster is drawn (the scene's geometry and its local media
// volumes, which volumetric shadows light through); a spot light gets a perspective projection
// over its outer cone, near and far around the scene's bounds — and, in global or height fog,
// the camera's view to its far plane (physics/shadow_fit.h).
// The map and its view depend on the scene's camera, lights, geometry and media alone (no
// jitter, no frame number): its cache key stays equal between frames, so a cached pass
// that reads them (opacity_shadow_map) can be skipped.
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/register_pass.h"
#include "physics/camera.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/scene_geometry.h"
#include "physics/shadow_fit.h"
#include "passes/plumbing/shadow_view.h"
#include "shaders/bindings/shadow.vert.h"
#include "shaders/include/shadow_filter_codes.h"

namespace volgraph {
namespace {

namespace shadow_vert_shader = shaders::shadow_vert;

// Why light `index` cannot cast this map's shadows ("" when it can): it must exist, be
// directional or spot, and cast shadows.
std::string shadow_light_problem(const Scene& scene, int64_t index) {
  if (index < 0 || index >= int64_t(scene.lights.size())) {
    return "light " + std::to_string(index) + " does not exist: scene.lights has " + std::to_string(scene.lights.size());
  }
  const Light& light = scene.lights[size_t(index)];
  if (light.type == LightType::point) {
    return "light " + std::to_string(index) + " is a point light; shadow_map takes a directional or spot light";
  }
  if (!light.cast_shadows) return "light " + std::to_string(index) + " has cast_shadows: false";
  return "";
}

std::vector<ParamProblem> check_light(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params);

struct ShadowMapTable : PassTable {
  ShadowMapTable()
      : PassTable("shadow_map", PassKind::graphics,
                  "Depth of the scene seen from a directional (fitted orthographic) or spot (perspective) light.") {
    decl.needs = feature_bit(SceneFeature::shadow_casting_light);
    decl.check_scene = check_light;
    // The directional fit follows the camera's frustum; the depth range holds the
    // geometry and the media volumes; a spot in fog reaches the camera's far plane.
    decl.reads_scene = part_bit(ScenePart::camera) | part_bit(ScenePart::lights) | part_bit(ScenePart::geometry) |
                       part_bit(ScenePart::media);
    decl.frame_invariant = true;
  }
  // Variants.
  VariantHandle pcf = variant("pcf", "percentage-closer filtering over a Poisson disc of pcf_radius texels", SHADOW_FILTER_PCF);
  VariantHandle hard = variant("hard", "one depth comparison per lookup", SHADOW_FILTER_HARD);
  // Parameters.
  ParamHandle<int64_t> light = integer("light", 0, 0, 63, "", "index of the light in scene.lights (directional or spot)");
  ParamHandle<int64_t> resolution = integer("resolution", 2048, 64, 16384, "texels", "side of the square shadow map");
  ParamHandle<double> depth_bias = number("depth_bias", 0.002, 0, 0.1, "", "constant bias, in the light's normalised depth");
  ParamHandle<double> slope_bias = number("slope_bias", 1.5, 0, 16, "", "bias scaled by the surface slope seen from the light");
  ParamHandle<double> pcf_radius = number("pcf_radius", 1.5, 0, 16, "texels", "filter radius of the pcf variant");
  ParamHandle<double> distance = number("distance", 0, 0, 1e6, "m",
                                        "directional: view depth up to which the camera's view receives shadows (0: to the far end of "
                                        "the scene's bounds)");
  // Slots.
  SlotHandle depth = output("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float,
                            SizeSpec::square_of(resolution), "light-space depth");
  SlotHandle light_view = output("light_view", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(256),
                                 "the light's view-projection matrix and bias, for passes that sample `depth`");
};

std::vector<ParamProblem> check_light(const PassDecl&, const Scene& scene, const std::vector<ParamValue>& params) {
  static const ShadowMapTable table;
  const std::string problem = shadow_light_problem(scene, param_in(params, table.light));
  if (problem.empty()) return {};
  return {{"light", problem}};
}

// Depth of the scene from the light (shaders/shadow.vert), alpha-masked texels cut
// (shadow_mask.frag); its view goes to light_view.
class ShadowMapExecution final : public PassExecution {
 public:
  explicit ShadowMapExecution(const ShadowMapTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    using namespace rhi;
    RenderPipelineDesc pd;
    pd.label = "shadow map";
    pd.vertex_buffers = {plumbing::SceneGeometry::position_uv_layout()};
    pd.depth = {Format::d32_float, true, CompareFunction::less, 0.0f, float(s.param(t_.slope_bias))};
    pd.cull = CullMode::none;
    masked_program_ = plumbing::create_render_program(s.device, pd, "shadow.vert", "shadow_mask.frag");
    pd.label = "shadow map (depth only)";
    program_ = plumbing::create_render_program(s.device, pd, "shadow.vert", "", masked_program_);
    geometry_ = std::make_unique<plumbing::SceneGeometry>(s.device, *s.scene, masked_program_);
    // The view block is written every frame (here and to light_view): its layout is checked once.
    plumbing::check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(program_, shadow_vert_shader::shadow, s.name() + " light_view");
    view_ = s.device.create_buffer({"shadow view", sizeof(plumbing::ShadowViewBlock), buffer_usage::uniform});
  }

  void record(PassContext& c) override {
    const int64_t index = c.param(t_.light);
    const std::optional<physics::Box> bounds = shadowed_bounds(c);
    const bool casts = shadow_light_problem(*c.scene, index).empty() && bounds;
    plumbing::ShadowViewBlock block{};
    block.params[0] = float(c.param(t_.depth_bias));
    block.params[1] = float(c.param(t_.pcf_radius));
    block.params[3] = casts ? float(index) : -1.0f;  // −1: no light is shadowed
    block.mode[0] = c.variant().shader_code;
    if (casts) {
      const physics::Mat4 view_projection = light_view_projection(c, c.scene->lights[size_t(index)], *bounds);
      physics::to_floats(view_projection, block.light_view_projection);
      physics::to_floats(physics::inverse(view_projection), block.clip_to_world);
    }
    const auto bytes = std::as_bytes(std::span(&block, 1));
    c.device.write_buffer(view_, 0, bytes);                    // for this pass's vertex shader
    c.encoder.update_buffer(c.buffer(t_.light_view), 0, bytes);  // for the passes that sample the map
    // Without a light to cast shadows (a pass kept by --no-cull) or anything to cast or
    // receive them, the map stays clear: nothing occludes anything.
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.depth = {c.view(t_.depth), rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    if (casts && !geometry_->objects().empty()) {
      const rhi::BindGroupId view = c.bind_group(program_, {bind(shadow_vert_shader::shadow, view_)});
      draw_casters(c, program_, view, plumbing::Surfaces::solid_shadow_casters);
      draw_casters(c, masked_program_, view, plumbing::Surfaces::masked_shadow_casters);
    }
    c.encoder.end_render_pass();
  }

 private:
  // The geometry's box and the media volumes the light's view must hold.
  std::optional<physics::Box> shadowed_bounds(const PassContext& c) const {
    std::optional<physics::Box> geometry;
    if (!geometry_->objects().empty()) geometry = physics::Box{geometry_->bounds_min(), geometry_->bounds_max()};
    return physics::shadowed_bounds(geometry, c.scene->media);
  }

  // The light's view and projection. Directional: fitted to the frame's camera, whose
  // aspect is the graph's frame size (what the scene pass renders unless its color size
  // is overridden); with no frame size known, fitted to the whole scene.
  physics::Mat4 light_view_projection(const PassContext& c, const Light& light, const physics::Box& scene) const {
    const Extent frame = c.frame_size();
    if (light.type == LightType::spot) {
      // Global or height fog is lit wherever the camera looks: the spot's depth range reaches
      // the camera's far plane, or fog behind a caster but beyond the scene's box would count as lit.
      const Media& media = c.scene->media;
      if (!media.fog && !media.height_fog) return physics::fit_spot(light, scene);
      const double aspect = frame.width && frame.height ? double(frame.width) / frame.height : 1.0;
      const Camera& camera = c.scene->camera;
      const auto corners = physics::frustum_slice_corners(camera, aspect, {camera.near, camera.far});
      return physics::fit_spot(light, physics::including(scene, corners));
    }
    if (frame.width == 0 || frame.height == 0) return physics::fit_directional_to_scene(light.direction, scene).view_projection();
    const Extent map = c.extent(t_.depth);
    const physics::ReceiverView view{c.scene->camera, double(frame.width) / frame.height, c.param(t_.distance), map.width,
                                     map.height};
    return physics::fit_directional_to_camera(light.direction, scene, view).view_projection();
  }

  const ShadowMapTable& t_;
  // The objects of `which`, when there are any, by `program` (one of the two sharing layouts).
  void draw_casters(PassContext& c, const plumbing::RenderProgram& program, rhi::BindGroupId view, plumbing::Surfaces which) {
    if (!geometry_->any(which)) return;
    c.encoder.set_pipeline(program.pipeline);
    c.encoder.set_bind_group(0, view);
    geometry_->draw(c.encoder, 1, which);
  }

  std::unique_ptr<plumbing::SceneGeometry> geometry_;
  plumbing::RenderProgram program_;         // depth only
  plumbing::RenderProgram masked_program_;  // alpha-tested: masked texels are holes
  rhi::BufferId view_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(ShadowMapTable, ShadowMapExecution);

}  // namespace volgraph
