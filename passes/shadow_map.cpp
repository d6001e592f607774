// Shadow map: depth of the scene from one light. A directional light gets an orthographic
// window fitted to the shadow receivers the camera sees (its frustum up to `distance`,
// clipped to the scene's bounds), snapped to whole texels, with its depth range over the
// whole scene so that every caster is drawn (the scene's geometry and its local media
// volumes, which volumetric shadows light through); a spot light gets a perspective projection
// over its outer cone, near and far around the scene's bounds — and, in global or height fog,
// the camera's view to its far plane (passes/shading/shadow_fit.h).
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/passes.h"
#include "passes/shading/camera.h"
#include "passes/shading/programs.h"
#include "passes/shading/scene_geometry.h"
#include "passes/shading/shadow_fit.h"
#include "passes/shading/shadow_view.h"

namespace volgraph {
namespace {

// The light's view and projection. Directional: fitted to the frame's camera, whose
// aspect is the graph's output size (what the scene pass renders unless its color size is
// overridden); with no output size known, fitted to the whole scene.
shading::Mat4 light_view_projection(const PassContext& c, const Light& light, const shading::Box& scene) {
  const Extent frame = c.graph.output_size;
  if (light.type == LightType::spot) {
    // Global or height fog is lit wherever the camera looks: the spot's depth range reaches
    // the camera's far plane, or fog behind a caster but beyond the scene's box would count as lit.
    const Media& media = c.scene->media;
    if (!media.fog && !media.height_fog) return shading::fit_spot(light, scene);
    const double aspect = frame.width && frame.height ? double(frame.width) / frame.height : 1.0;
    const Camera& camera = c.scene->camera;
    const auto corners = shading::frustum_slice_corners(camera, aspect, {camera.near, camera.far});
    return shading::fit_spot(light, shading::including(scene, corners));
  }
  if (frame.width == 0 || frame.height == 0) return shading::fit_directional_to_scene(light.direction, scene).view_projection();
  const Extent map = c.desc("depth").extent;
  const shading::ReceiverView view{c.scene->camera, double(frame.width) / frame.height,
                                   std::get<double>(c.param("distance")), map.width, map.height};
  return shading::fit_directional_to_camera(light.direction, scene, view).view_projection();
}

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

// Depth of the scene from the light (shaders/shadow.vert); its view goes to light_view.
class ShadowMapExecution final : public PassExecution {
 public:
  void record(PassContext& c) override {
    if (!program_.pipeline) prepare(c);
    const int64_t index = std::get<int64_t>(c.param("light"));
    const std::optional<shading::Box> bounds = shadowed_bounds(c);
    const bool casts = shadow_light_problem(*c.scene, index).empty() && bounds;
    shading::ShadowViewBlock block{};
    block.params[0] = float(std::get<double>(c.param("depth_bias")));
    block.params[1] = float(std::get<double>(c.param("pcf_radius")));
    block.params[3] = casts ? float(index) : -1.0f;  // −1: no light is shadowed
    block.mode[0] = c.variant() == "pcf" ? 1 : 0;
    if (casts) {
      const shading::Mat4 view_projection = light_view_projection(c, c.scene->lights[size_t(index)], *bounds);
      to_floats(view_projection, block.light_view_projection);
      to_floats(shading::inverse(view_projection), block.clip_to_world);
    }
    const auto bytes = std::as_bytes(std::span(&block, 1));
    c.device.write_buffer(view_, 0, bytes);           // for this pass's vertex shader
    c.encoder.update_buffer(c.buffer("light_view"), 0, bytes);  // for the passes that sample the map
    // Without a light to cast shadows (a pass kept by --no-cull) or anything to cast or
    // receive them, the map stays clear: nothing occludes anything.
    rhi::RenderPassDesc pass;
    pass.label = c.graph_pass().name;
    pass.depth = {c.view("depth"), rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    if (casts && !geometry_->objects().empty()) {
      c.encoder.set_pipeline(program_.pipeline);
      c.encoder.set_bind_group(0, view_group_);
      geometry_->draw(c.encoder, 1);
    }
    c.encoder.end_render_pass();
  }

 private:
  // The geometry's box and the media volumes the light's view must hold.
  std::optional<shading::Box> shadowed_bounds(const PassContext& c) const {
    std::optional<shading::Box> geometry;
    if (!geometry_->objects().empty()) geometry = shading::Box{geometry_->bounds_min(), geometry_->bounds_max()};
    return shading::shadowed_bounds(geometry, c.scene->media);
  }

  void prepare(PassContext& c) {
    using namespace rhi;
    RenderPipelineDesc pd;
    pd.label = "shadow map";
    pd.vertex_buffers = {shading::SceneGeometry::position_layout()};
    pd.depth = {Format::d32_float, true, CompareFunction::less, 0.0f, float(std::get<double>(c.param("slope_bias")))};
    pd.cull = CullMode::none;
    program_ = shading::create_render_program(c.device, pd, "shadow.vert", "");
    geometry_ = std::make_unique<shading::SceneGeometry>(c.device, *c.scene, program_.layout_descs[1], program_.layouts[1]);
    view_ = c.device.create_buffer({"shadow view", sizeof(shading::ShadowViewBlock), buffer_usage::uniform});
    view_group_ = c.device.create_bind_group({"shadow view", program_.layouts[0], {BindGroupEntry::of(0, view_)}});
  }

  std::unique_ptr<shading::SceneGeometry> geometry_;
  shading::RenderProgram program_;
  rhi::BufferId view_;
  rhi::BindGroupId view_group_;
};

std::vector<ParamProblem> check_light(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params) {
  const std::string problem = shadow_light_problem(scene, std::get<int64_t>(params[size_t(decl.param_index("light"))]));
  if (problem.empty()) return {};
  return {{"light", problem}};
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
      param_number("distance", 0, 0, 1e6, "m",
                   "directional: view depth up to which the camera's view receives shadows (0: to the far end of "
                   "the scene's bounds)"),
  };
  d.slots = {
      slot_out("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float,
               SizeSpec::square_of("resolution"), "light-space depth"),
      slot_out("light_view", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(256),
               "the light's view-projection matrix and bias, for passes that sample `depth`"),
  };
  d.needs = feature_bit(SceneFeature::shadow_casting_light);
  d.check_scene = check_light;
  d.make_execution = [] { return std::unique_ptr<PassExecution>(new ShadowMapExecution()); };
  return d;
}

}  // namespace volgraph
