// Translucent shadow map (RTR4 §7.8 and §14.5.1; Frostbite/HDRP style): over a shadow_map's
// light view, the coloured transmittance of the translucent shadow casters in front of the
// opaque map — each caster multiplies the texel (cleared to 1) by its layer transmittance
// (physics::surface_layer, translucency.glsl: the translucency pass's function for light
// crossing the object) — and the light-space depth of the nearest one, so a receiver is
// tinted only where it lies behind them (translucent_shadow_lookup.glsl). Its own pass, not
// a variant of shadow_map: graphs without translucent casters pay nothing, and the graph culls
// it where nothing reads it.
#include <memory>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/scene_geometry.h"
#include "passes/plumbing/shadow_view.h"
#include "shaders/bindings/translucent_shadow.frag.h"

namespace volgraph {
namespace {

namespace caster_shader = shaders::translucent_shadow_frag;

struct TranslucentShadowMapTable : PassTable {
  TranslucentShadowMapTable()
      : PassTable("translucent_shadow_map", PassKind::graphics,
                  "Coloured transmittance of the translucent shadow casters over a shadow_map's light view, and their nearest depth.") {
    decl.needs = feature_bit(SceneFeature::shadow_casting_light);
    // The light view comes from shadow_map.light_view; the casters are the scene's geometry.
    decl.reads_scene = part_bit(ScenePart::geometry);
    decl.frame_invariant = true;
  }
  // Variants.
  VariantHandle multiply = variant("multiply", "every translucent caster in front of the opaque map multiplies its texels by its transmittance");
  // Parameters.
  ParamHandle<int64_t> resolution = integer("resolution", 2048, 64, 16384, "texels", "side of the square map (the shadow map's, best)");
  // Slots.
  SlotHandle shadow_map = input("shadow_map", ResourceKind::texture2d, Usage::sampled, "the opaque casters' depth (shadow_map.depth): casters behind it do not count",
                                {.format = Format::d32_float});
  SlotHandle light_view = input("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view (shadow_map.light_view)");
  SlotHandle transmittance = output("transmittance", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float,
                                    SizeSpec::square_of(resolution), "product of the casters' transmittances along each light ray (1: none)");
  SlotHandle depth = output("depth", ResourceKind::texture2d, Usage::depth_attachment, Format::d32_float, SizeSpec::square_of(resolution),
                            "light-space depth of the nearest translucent caster (1: none)");
};

// Two draws of the translucent casters into one render pass: × their transmittance (no depth
// test: every caster counts), then their depth (test less, colour × 1).
class TranslucentShadowMapExecution final : public PassExecution {
 public:
  explicit TranslucentShadowMapExecution(const TranslucentShadowMapTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    using namespace rhi;
    RenderPipelineDesc pd;
    pd.label = "translucent shadow map";
    pd.vertex_buffers = {plumbing::SceneGeometry::vertex_layout()};
    pd.colors = {{Format::rgba16_float, BlendMode::multiply}};
    pd.depth = {Format::d32_float, false, CompareFunction::always};
    pd.cull = CullMode::none;  // a sheet is crossed from either side
    transmittance_program_ = plumbing::create_render_program(s.device, pd, "translucent_shadow.vert", "translucent_shadow.frag");
    pd.label = "translucent shadow map (depth)";
    pd.depth = {Format::d32_float, true, CompareFunction::less};
    depth_program_ =
        plumbing::create_render_program(s.device, pd, "translucent_shadow.vert", "translucent_shadow_depth.frag", transmittance_program_);
    plumbing::check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(transmittance_program_, caster_shader::shadow,
                                                                      s.name() + " light_view");
    geometry_ = std::make_unique<plumbing::SceneGeometry>(s.device, *s.scene, transmittance_program_);
  }

  void record(PassContext& c) override {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.transmittance), rhi::LoadOp::clear, {1.0f, 1.0f, 1.0f, 1.0f}}};
    pass.depth = {c.view(t_.depth), rhi::LoadOp::clear, 1.0f, false};
    c.encoder.begin_render_pass(pass);
    if (geometry_->any(plumbing::Surfaces::translucent_shadow_casters)) {
      const rhi::BindGroupId view = c.bind_group(transmittance_program_, {bind(caster_shader::shadow, c.buffer(t_.light_view)),
                                                                          bind(caster_shader::opaque_depth, c.view(t_.shadow_map)),
                                                                          bind(caster_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))});
      for (const plumbing::RenderProgram* program : {&transmittance_program_, &depth_program_}) {
        c.encoder.set_pipeline(program->pipeline);
        c.encoder.set_bind_group(0, view);
        geometry_->draw(c.encoder, 1, plumbing::Surfaces::translucent_shadow_casters);
      }
    }
    c.encoder.end_render_pass();
  }

 private:
  const TranslucentShadowMapTable& t_;
  std::unique_ptr<plumbing::SceneGeometry> geometry_;
  plumbing::RenderProgram transmittance_program_;  // × transmittance
  plumbing::RenderProgram depth_program_;          // nearest depth, sharing its layouts
};

}  // namespace

VOLGRAPH_REGISTER_PASS(TranslucentShadowMapTable, TranslucentShadowMapExecution);

}  // namespace volgraph
