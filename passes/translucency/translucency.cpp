// translucency: the scene's translucent surfaces (RTR4 §14.5.1) over the lit, fogged
// opaque colour. Each surface is a layer, C = radiance + transmittance ⊙ C_behind
// (physics::surface_layer, shaders/include/translucent_surface.glsl), lit as the opaque
// scene is (the scene pass's own frame block), and seen through the froxel volume's
// media and the aerial-perspective volume's air in front of it where they are wired
// (physics::fogged_layer, the fog then the air, as the graphs apply them to the opaque
// colour); with a translucent_shadow_map wired beside the shadow map, a surface behind
// other translucent surfaces as the light sees it is lit through their transmittance
// (RTR4 §14.5.1). Variants compose the layers:
// - sorted: object by object from the farthest (their bounds' centres) to the nearest,
//   each drawn twice — × its transmittance, then + its radiance (coloured transmittance
//   with plain blending) — a double-sided one back faces first; or, where the device
//   offers dual-source blending (`dual_source`), a convex object once: radiance + colour ×
//   transmittance (the fragment's second output the destination's factor). Exact where each object
//   covers a pixel at most once per face set (convex objects, planes).
// - weighted_oit: every surface in one draw in any order (McGuire & Bavoil 2013, with
//   McGuire 2015's coloured transmission): the transmittances multiply exactly (their
//   optical depths add), the radiance is a depth-weighted mean; resolved onto the colour
//   in two draws.
// - depth_peeling: the layers in exact back-to-front order per pixel (Everitt 2001,
//   peeled from the back): each layer's depth is the farthest surface in front of the one
//   peeled before, then every surface at exactly that depth is shaded as in sorted. A
//   convex solid costs two layers (its back faces end its inside path and shade nothing);
//   with fewer layers than a pixel has, the nearest ones are left out.
// In sorted and weighted_oit solid objects' paths inside end at their back faces (a step
// draws them into back_depth, and their float32 distance into back_distance) or at the
// opaque surface, whichever is nearer: convex solids, one per pixel; in depth_peeling at
// the layer behind (its distance written beside its depth).
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/plumbing/scene_geometry.h"
#include "passes/plumbing/scene_lighting.h"
#include "passes/plumbing/shadow_view.h"
#include "passes/plumbing/textures.h"
#include "passes/register_pass.h"
#include "passes/uniform_mirrors.h"
#include "physics/camera.h"
#include "shaders/include/translucency_params.h"
#include "shaders/bindings/translucency_oit_revealage.frag.h"
#include "shaders/bindings/translucency_refract.frag.h"

namespace volgraph {
namespace {

// The surface programs share translucency_refract.frag's layouts (it reads every binding
// of their sets); the two resolve shaders declare the same bindings.
namespace translucency_surface_shader = shaders::translucency_refract_frag;
namespace translucency_resolve_shader = shaders::translucency_oit_revealage_frag;

constexpr int64_t kMaxPeeledLayers = 16;

// depth_peeling's two steps per layer.
struct PeelSteps {
  StepHandle depth, shade;
};

// What a solid of IOR ≠ 1 shows behind it (the `refraction` choice).
enum class Refraction { screen_space, none };
// The shape a refracting solid is taken to have where its ray leaves it (`refraction_shape`).
enum class RefractionShape { slab, sphere };

struct TranslucencyTable : PassTable {
  TranslucencyTable()
      : PassTable("translucency", PassKind::graphics,
                  "Translucent surfaces (coverage, coloured transmittance through a thin wall, shell or solid, Fresnel reflection) "
                  "over the scene's colour, lit as the opaque scene and fogged at their own depth.") {
    decl.needs = feature_bit(SceneFeature::translucent_objects);
  }
  // Variants.
  VariantHandle sorted = variant("sorted", "objects from the farthest to the nearest, each × its transmittance then + its radiance");
  VariantHandle weighted_oit = variant(
      "weighted_oit", "weighted blended order-independent transparency (McGuire & Bavoil 2013; coloured transmission, McGuire 2015)");
  VariantHandle depth_peeling = variant(
      "depth_peeling", "each pixel's layers in exact back-to-front order, peeled from the back (Everitt 2001); up to `layers` of them");
  // Parameters.
  ParamHandle<bool> shadows = flag("shadows", true, "sample the shadow map when one is wired");
  ChoiceHandle<Refraction> refraction =
      choice("refraction", Refraction::screen_space, {{Refraction::screen_space, "screen_space"}, {Refraction::none, "none"}},
             "sorted: solids of IOR ≠ 1 show refracted_color where their refracted ray lands (Sousa 2005; the slab approximation), "
             "when it is wired; none: what lies straight behind");
  ChoiceHandle<RefractionShape> refraction_shape =
      choice("refraction_shape", RefractionShape::slab, {{RefractionShape::slab, "slab"}, {RefractionShape::sphere, "sphere"}},
             "screen_space: where a solid's refracted ray leaves it — slab: parallel to the view ray, displaced (exact for plane-parallel "
             "panes); sphere: bent out of the sphere tangent at the entry whose chord is the path inside (HDRP's sphere model; exact for spheres)");
  ParamHandle<bool> dual_source = flag("dual_source", true,
                                       "sorted and depth_peeling: one draw a layer (radiance + colour × transmittance, dual-source "
                                       "blending) where the device offers it, else two");
  ParamHandle<int64_t> layers = integer("layers", 8, 1, kMaxPeeledLayers, "layers",
                                        "depth_peeling: the layers peeled a pixel (the farthest first; a convex solid is two)");
  // Slots.
  SlotHandle color = inout("color", ResourceKind::texture2d, Usage::color_attachment_load, "the scene's linear radiance, fogged");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the opaque scene's depth", {.format = Format::d32_float});
  SlotHandle frame = input("frame", ResourceKind::buffer, Usage::uniform_read, "the scene pass's lighting block (scene.frame)");
  SlotHandle shadow_map = optional_input("shadow_map", ResourceKind::texture2d, Usage::sampled, "depth from shadow_map",
                                         {.format = Format::d32_float});
  SlotHandle light_view = optional_input("light_view", ResourceKind::buffer, Usage::uniform_read, "the shadow map's view");
  SlotHandle translucent_shadow = optional_input("translucent_shadow", ResourceKind::texture2d, Usage::sampled,
                                                 "translucent_shadow_map's transmittance over the same light view: a surface behind "
                                                 "another translucent one as the light sees it is lit through it");
  SlotHandle translucent_shadow_depth = optional_input("translucent_shadow_depth", ResourceKind::texture2d, Usage::sampled,
                                                       "translucent_shadow_map's depth: only surfaces behind its casters are tinted",
                                                       {.format = Format::d32_float});
  SlotHandle fog_frame = optional_input("fog_frame", ResourceKind::buffer, Usage::uniform_read, "froxel_voxelize's frame block");
  SlotHandle integrated_scattering = optional_input("integrated_scattering", ResourceKind::texture3d, Usage::sampled,
                                                    "from scatter_integrate: the media in front of each surface");
  SlotHandle integrated_transmittance =
      optional_input("integrated_transmittance", ResourceKind::texture3d, Usage::sampled, "from scatter_integrate");
  SlotHandle refracted_color = optional_input("refracted_color", ResourceKind::texture2d, Usage::sampled,
                                              "a copy of `color` before this pass: what refracting solids show (generate_mips.mips: a rough "
                                              "interface reads the level its refracted cone spans, refraction_blur_lod)");
  SlotHandle environment = optional_input("environment", ResourceKind::texture_cube, Usage::sampled,
                                          "a cube of the radiance around (sky_cube.cube): what the surfaces reflect toward the mirrored view "
                                          "ray, and what refracted rays screen space cannot follow (off the screen, behind the camera, the sky) "
                                          "see toward their way out; without it the background's (or the sky's mean) uniform radiance");
  SlotHandle aerial_lookup =
      optional_input("aerial_lookup", ResourceKind::buffer, Usage::uniform_read, "atmosphere_aerial_perspective's lookup: the air in front of each surface");
  SlotHandle aerial_scattering = optional_input("aerial_scattering", ResourceKind::texture3d, Usage::sampled, "from atmosphere_aerial_perspective");
  SlotHandle aerial_transmittance =
      optional_input("aerial_transmittance", ResourceKind::texture3d, Usage::sampled, "from atmosphere_aerial_perspective");
  // Internal targets.
  SlotHandle back_depth = internal("back_depth", ResourceKind::texture2d, Format::d32_float, SizeSpec::of_output(),
                                   "the nearest back face of the solid translucent objects");
  // A solid's path ends at its back face's distance read as float32: a 32-bit depth at 30 m
  // (near 0.05 m) resolves only ~1 mm, 2e-3 of a 0.5 m path, over an fp16 step (1e-3).
  SlotHandle back_distance = internal("back_distance", ResourceKind::texture2d, Format::r32_float, SizeSpec::of_output(),
                                      "the distance (m) from the camera to back_depth's surface (depth_peeling: the odd layers')");
  SlotHandle oit_accumulation = internal("oit_accumulation", ResourceKind::texture2d, Format::rgba16_float, SizeSpec::of_output(),
                                         "weighted_oit: Σ w·radiance, Σ w·opacity");
  SlotHandle oit_optical_depth = internal("oit_optical_depth", ResourceKind::texture2d, Format::rgba16_float, SizeSpec::of_output(),
                                      "weighted_oit: Σ −ln T per channel, the layers' transmittances multiplied");
  SlotHandle peel_depth = internal("peel_depth", ResourceKind::texture2d, Format::d32_float, SizeSpec::of_output(),
                                   "depth_peeling: the even layers' depth (back_depth holds the odd ones')");
  SlotHandle peel_distance = internal("peel_distance", ResourceKind::texture2d, Format::r32_float, SizeSpec::of_output(),
                                      "depth_peeling: the distance (m) from the camera to peel_depth's surface");
  // Steps.
  // depth_peeling clears back_depth to the far plane: nothing peeled yet.
  StepHandle back_faces = step("back_faces", PassKind::graphics,
                               with_surface_inputs({{back_depth, Usage::depth_attachment}, {back_distance, Usage::color_attachment}}));
  StepHandle surfaces = step("surfaces", PassKind::graphics,
                             with_surface_inputs({{color, Usage::color_attachment_load}, {back_depth, Usage::sampled},
                                                  {back_distance, Usage::sampled}, {refracted_color, Usage::sampled}}),
                             only_in({sorted}));
  StepHandle accumulate = step("accumulate", PassKind::graphics,
                               with_surface_inputs({{oit_accumulation, Usage::color_attachment}, {oit_optical_depth, Usage::color_attachment},
                                                    {back_depth, Usage::sampled}, {back_distance, Usage::sampled}}),
                               only_in({weighted_oit}));
  StepHandle resolve = step("resolve", PassKind::graphics,
                            {{color, Usage::color_attachment_load}, {oit_accumulation, Usage::sampled}, {oit_optical_depth, Usage::sampled}},
                            only_in({weighted_oit}));
  // depth_peeling, layer k (k < layers): its depth, then the surfaces at that depth.
  std::array<PeelSteps, kMaxPeeledLayers> peel = peel_steps();

  // Layer k's depth target, and the layer peeled before it (its fragments lie in front of it).
  SlotHandle layer_depth(size_t k) const { return k % 2 == 0 ? peel_depth : back_depth; }
  SlotHandle behind_layer(size_t k) const { return k % 2 == 0 ? back_depth : peel_depth; }
  // Their distances (m) from the camera, written beside the depths.
  SlotHandle layer_distance(size_t k) const { return k % 2 == 0 ? peel_distance : back_distance; }
  SlotHandle behind_distance(size_t k) const { return k % 2 == 0 ? back_distance : peel_distance; }

 private:
  std::array<PeelSteps, kMaxPeeledLayers> peel_steps() {
    std::array<PeelSteps, kMaxPeeledLayers> steps;
    for (size_t k = 0; k < steps.size(); ++k) {
      const StepCondition while_peeled = only_in_while(depth_peeling, layers, int64_t(k));
      const std::string layer = std::to_string(k);
      steps[k].depth = step("peel_depth_" + layer, PassKind::graphics,
                            with_surface_inputs({{layer_depth(k), Usage::depth_attachment}, {layer_distance(k), Usage::color_attachment},
                                                 {behind_layer(k), Usage::sampled}}),
                            while_peeled);
      steps[k].shade = step("peel_shade_" + layer, PassKind::graphics,
                            with_surface_inputs({{color, Usage::color_attachment_load}, {layer_depth(k), Usage::depth_read},
                                                 {behind_layer(k), Usage::sampled}, {behind_distance(k), Usage::sampled},
                                                 {refracted_color, Usage::sampled}}),
                            while_peeled);
    }
    return steps;
  }
  // What every step that shades surfaces reads, beside its own targets.
  std::vector<std::pair<SlotHandle, Usage>> with_surface_inputs(std::vector<std::pair<SlotHandle, Usage>> uses) const {
    for (const SlotHandle s : {depth, shadow_map, translucent_shadow, translucent_shadow_depth, integrated_scattering,
                               integrated_transmittance, aerial_scattering, aerial_transmittance, environment}) {
      uses.push_back({s, Usage::sampled});
    }
    for (const SlotHandle s : {frame, light_view, fog_frame, aerial_lookup}) uses.push_back({s, Usage::uniform_read});
    return uses;
  }
};

// The surfaces' programs: one per blend and face set, sharing one set of bind group layouts.
struct SurfacePrograms {
  plumbing::RenderProgram transmittance_back, radiance_back, transmittance_front, radiance_front;  // sorted
  plumbing::RenderProgram refract_front;  // sorted: a refracting solid's first draw (replaces)
  plumbing::RenderProgram accumulate_all, accumulate_front;                                       // weighted_oit
  plumbing::RenderProgram back_depth;                                                             // the back faces' depth
  // depth_peeling: a layer's depth, then its surfaces at exactly that depth (as sorted draws
  // them: both faces of the rest, the front faces of solids, a refracting solid replacing).
  plumbing::RenderProgram peel_depth, peel_transmittance_all, peel_radiance_all, peel_transmittance_front, peel_radiance_front,
      peel_refract_front;
  // With dual-source blending: each of the pairs above (but a refracting solid's) in one draw.
  plumbing::RenderProgram layer_back, layer_front, peel_layer_all, peel_layer_front;
};

// One translucent layer over the colour: two draws (× transmittance, + radiance), or one
// with dual-source blending (`combined`, when it has a pipeline).
struct LayerPrograms {
  const plumbing::RenderProgram& attenuate;
  const plumbing::RenderProgram& add;
  const plumbing::RenderProgram& combined;
};

class TranslucencyExecution final : public PassExecution {
 public:
  explicit TranslucencyExecution(const TranslucencyTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    using rhi::BlendMode;
    using rhi::CullMode;
    const Format color = s.desc(t_.color).format;
    const auto surface = [&](const char* label, const char* fragment, std::vector<rhi::ColorTargetState> targets, CullMode cull,
                             const plumbing::RenderProgram* like, rhi::DepthStencilState depth = {}) {
      rhi::RenderPipelineDesc pd;
      pd.label = s.name() + " " + label;
      pd.vertex_buffers = {plumbing::SceneGeometry::vertex_layout()};
      pd.colors = std::move(targets);
      pd.cull = cull;
      pd.depth = depth;
      return like ? plumbing::create_render_program(s.device, pd, "scene.vert", fragment, *like)
                  : plumbing::create_render_program(s.device, pd, "scene.vert", fragment);
    };
    SurfacePrograms& p = programs_;
    note_layer_draws(s);
    // The refracting draw reads every binding the surfaces' sets hold: the others share its layouts.
    p.refract_front = surface("refracted × transmittance", "translucency_refract.frag", {{color, BlendMode::replace}}, CullMode::back, nullptr);
    const plumbing::RenderProgram* like = &p.refract_front;
    p.transmittance_back = surface("× transmittance (back faces)", "translucency_transmittance.frag", {{color, BlendMode::multiply}},
                                   CullMode::front, like);
    p.radiance_back = surface("+ radiance (back faces)", "translucency_radiance.frag", {{color, BlendMode::additive}}, CullMode::front, like);
    p.transmittance_front = surface("× transmittance", "translucency_transmittance.frag", {{color, BlendMode::multiply}}, CullMode::back, like);
    p.radiance_front = surface("+ radiance", "translucency_radiance.frag", {{color, BlendMode::additive}}, CullMode::back, like);
    const std::vector<rhi::ColorTargetState> oit = {{Format::rgba16_float, BlendMode::additive}, {Format::rgba16_float, BlendMode::additive}};
    p.accumulate_all = surface("accumulate", "translucency_accumulate.frag", oit, CullMode::none, like);
    p.accumulate_front = surface("accumulate (front faces)", "translucency_accumulate.frag", oit, CullMode::back, like);
    {
      rhi::RenderPipelineDesc pd;
      pd.label = s.name() + " back faces' depth";
      pd.vertex_buffers = {plumbing::SceneGeometry::vertex_layout()};
      pd.depth = {Format::d32_float, true, rhi::CompareFunction::less};
      pd.colors = {{Format::r32_float, BlendMode::replace}};  // the kept face's distance
      pd.cull = CullMode::front;
      p.back_depth = plumbing::create_render_program(s.device, pd, "scene.vert", "translucency_depth.frag", *like);
    }
    // Peeling keeps the farthest surface in front of the layer before; its shading matches that depth exactly
    // (scene.vert's invariant position).
    p.peel_depth = surface("peeled layer's depth", "translucency_peel_depth.frag", {{Format::r32_float, BlendMode::replace}}, CullMode::none, like,
                           {Format::d32_float, true, rhi::CompareFunction::greater});
    const rhi::DepthStencilState at_layer = {Format::d32_float, false, rhi::CompareFunction::equal};
    p.peel_transmittance_all = surface("peeled × transmittance", "translucency_transmittance.frag", {{color, BlendMode::multiply}},
                                       CullMode::none, like, at_layer);
    p.peel_radiance_all = surface("peeled + radiance", "translucency_radiance.frag", {{color, BlendMode::additive}}, CullMode::none, like, at_layer);
    p.peel_transmittance_front = surface("peeled × transmittance (front faces)", "translucency_transmittance.frag",
                                         {{color, BlendMode::multiply}}, CullMode::back, like, at_layer);
    p.peel_radiance_front = surface("peeled + radiance (front faces)", "translucency_radiance.frag", {{color, BlendMode::additive}},
                                    CullMode::back, like, at_layer);
    p.peel_refract_front = surface("peeled refracted × transmittance", "translucency_refract.frag", {{color, BlendMode::replace}},
                                   CullMode::back, like, at_layer);
    if (one_draw_per_layer(s)) {
      const BlendMode over = BlendMode::source_plus_dest_times_source1;
      const char* fragment = "translucency_radiance_transmittance.frag";
      p.layer_back = surface("radiance + × transmittance (back faces)", fragment, {{color, over}}, CullMode::front, like);
      p.layer_front = surface("radiance + × transmittance", fragment, {{color, over}}, CullMode::back, like);
      p.peel_layer_all = surface("peeled radiance + × transmittance", fragment, {{color, over}}, CullMode::none, like, at_layer);
      p.peel_layer_front =
          surface("peeled radiance + × transmittance (front faces)", fragment, {{color, over}}, CullMode::back, like, at_layer);
    }
    resolve_ = {resolve_program(s, color, BlendMode::multiply, "translucency_oit_revealage.frag"),
                resolve_program(s, color, BlendMode::additive, "translucency_oit_radiance.frag")};
    namespace shader = translucency_surface_shader;
    plumbing::check_wrapped_uniform_mirror<gpu::SceneFrame>(*like, shader::frame, s.name() + " frame (the scene pass's)");
    plumbing::check_wrapped_uniform_mirror<plumbing::ShadowViewBlock>(*like, shader::shadow, s.name() + " light_view");
    plumbing::check_wrapped_uniform_mirror<gpu::FogFrame>(*like, shader::fog, s.name() + " fog_frame");
    plumbing::check_wrapped_uniform_mirror<gpu::AerialLookup>(*like, shader::air, s.name() + " aerial_lookup");
    block_ = plumbing::create_shared_uniform_block(s.device, *like, shader::translucency, s.name() + " translucency", gpu::TranslucencyParams{});
    geometry_ = std::make_unique<plumbing::SceneGeometry>(s.device, *s.scene, *like);
    textures_ = std::make_unique<plumbing::TextureCache>(s.device);
    make_stand_ins(s);
  }

  // Whether a layer is one draw (dual-source blending) or two, said in the plan with why.
  // weighted_oit keeps its own accumulation (its layers add weighted sums, nothing multiplies
  // the colour before the resolve).
  bool one_draw_per_layer(const PassSetup& s) const {
    return !s.variant_is(t_.weighted_oit) && s.param(t_.dual_source) && s.device.has_dual_source_blending();
  }
  void note_layer_draws(const PassSetup& s) const {
    if (s.variant_is(t_.weighted_oit)) return s.note("weighted_oit: its own accumulation, no per-layer blend to fuse");
    if (!s.param(t_.dual_source)) return s.note("two draws a layer (× transmittance, + radiance): dual_source is off");
    if (!s.device.has_dual_source_blending()) {
      return s.note("two draws a layer (× transmittance, + radiance): the " + s.device.info().backend +
                    " device does not offer dual-source blending");
    }
    s.note("one draw a layer (radiance + colour × transmittance): dual-source blending, offered by the " + s.device.info().backend +
           " device" +
           (s.variant_is(t_.sorted) ? " (non-convex objects: two, as before)" : ""));
  }

  void record(PassContext& c) override {
    if (c.step_is(t_.back_faces)) return record_back_faces(c);
    if (c.step_is(t_.surfaces) && c.variant_is(t_.sorted)) return record_sorted(c);
    if (c.step_is(t_.accumulate) && c.variant_is(t_.weighted_oit)) return record_accumulate(c);
    if (c.step_is(t_.resolve) && c.variant_is(t_.weighted_oit)) return record_resolve(c);
    for (size_t k = 0; k < t_.peel.size(); ++k) {
      if (c.step_is(t_.peel[k].depth)) return record_peel_depth(c, k);
      if (c.step_is(t_.peel[k].shade)) return record_peel_shade(c, k);
    }
  }

 private:
  static plumbing::RenderProgram resolve_program(const PassSetup& s, Format color, rhi::BlendMode blend, const char* fragment) {
    rhi::RenderPipelineDesc pd;
    pd.label = s.name() + " " + fragment;
    pd.colors = {{color, blend}};
    return plumbing::create_render_program(s.device, pd, "fullscreen.vert", fragment);
  }

  // What the sets bind where nothing is wired: a shadow view that shadows no light, a
  // froxel frame and volume the shader does not read (options.x = 0).
  void make_stand_ins(PassSetup& s) {
    plumbing::ShadowViewBlock no_shadow{};
    no_shadow.params[3] = -1;
    no_shadow_view_ = plumbing::create_uniform_buffer(s.device, s.name() + " no shadow view", std::as_bytes(std::span(&no_shadow, 1)));
    const gpu::FogFrame no_fog{};
    no_fog_frame_ = plumbing::create_uniform_buffer(s.device, s.name() + " no froxel frame", std::as_bytes(std::span(&no_fog, 1)));
    rhi::TextureDesc volume;
    volume.label = s.name() + " no froxel volume";
    volume.kind = ResourceKind::texture3d;
    volume.format = Format::rgba16_float;
    volume.size = {1, 1, 1};
    volume.usage = rhi::texture_usage::sampled | rhi::texture_usage::copy_dst;
    no_volume_texture_ = s.device.create_texture(volume);
    const std::array<std::byte, 8> zero{};
    s.device.write_texture(no_volume_texture_, zero);
    no_volume_ = s.device.create_view(no_volume_texture_);
    rhi::TextureDesc cube = volume;
    cube.label = s.name() + " no environment cube";
    cube.kind = ResourceKind::texture_cube;
    cube.size = {1, 1, 1};
    no_environment_texture_ = s.device.create_texture(cube);
    const std::array<std::byte, 8 * 6> black_faces{};
    s.device.write_texture(no_environment_texture_, black_faces);
    no_environment_ = s.device.create_view(no_environment_texture_);
    const std::vector<std::byte> no_air(kAerialLookupBytes);
    no_aerial_lookup_ = plumbing::create_uniform_buffer(s.device, s.name() + " no aerial lookup", no_air);
  }

  void write_block(PassContext& c) {
    const Scene& scene = *c.scene;
    gpu::TranslucencyParams b{};
    for (size_t i = 0; i < 3; ++i) b.camera[i] = float(scene.camera.position[i]);
    b.camera[3] = float(scene.camera.near);
    // The environment the reflection sees: the background, or under an atmosphere the sky's mean radiance.
    const Vec3 environment = scene.atmosphere ? lighting_.sky_ambient_radiance(scene) : scene.background;
    for (size_t i = 0; i < 3; ++i) b.environment[i] = float(environment[i]);
    b.environment[3] = float(scene.camera.far);
    b.options[0] = fogged(c) ? 1.0f : 0.0f;
    b.options[1] = aired(c) ? 1.0f : 0.0f;
    b.options[2] = refracting(c) ? 1.0f : 0.0f;
    b.options[3] = float(2 * std::tan(scene.camera.fov_y_deg * M_PI / 360) / double(c.frame_size().height));  // a pixel's angle
    b.refraction[0] = c.param(t_.refraction_shape) == RefractionShape::sphere ? 1.0f : 0.0f;
    b.refraction[1] = c.bound(t_.environment) ? 1.0f : 0.0f;
    c.device.write_buffer(block_, 0, std::as_bytes(std::span(&b, 1)));
  }

  bool fogged(const PassSetup& c) const {
    return c.bound(t_.fog_frame) && c.bound(t_.integrated_scattering) && c.bound(t_.integrated_transmittance);
  }
  bool refracting(const PassSetup& c) const { return c.bound(t_.refracted_color) && c.param(t_.refraction) == Refraction::screen_space; }
  bool aired(const PassSetup& c) const {
    return c.bound(t_.aerial_lookup) && c.bound(t_.aerial_scattering) && c.bound(t_.aerial_transmittance);
  }
  bool shadowed(const PassSetup& c) const { return c.bound(t_.shadow_map) && c.bound(t_.light_view) && c.param(t_.shadows); }
  bool tinted(const PassSetup& c) const {
    return shadowed(c) && c.bound(t_.translucent_shadow) && c.bound(t_.translucent_shadow_depth);
  }

  // Sets 0, 2 and 3 of the surface programs; `back` the solid objects' back-face depth and
  // `back_distance` its distance (stand-ins while they are being drawn), `refracted` the
  // colour refracting solids show (a stand-in in the steps that do not declare reading it).
  void bind_surface_sets(PassContext& c, rhi::TextureViewId back, rhi::TextureViewId back_distance, rhi::TextureViewId refracted) {
    namespace shader = translucency_surface_shader;
    const plumbing::RenderProgram& p = programs_.transmittance_back;
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    c.encoder.set_bind_group(0, c.bind_group(p, {bind(shader::frame, c.buffer(t_.frame)), bind(shader::translucency, block_),
                                                 bind(shader::scene_depth, c.view(t_.depth)), bind(shader::back_depth, back),
                                                 bind(shader::nearest, nearest), bind(shader::refracted_color, refracted),
                                                 bind(shader::back_distance, back_distance),
                                                 bind(shader::environment_cube, c.bound(t_.environment) ? c.view(t_.environment) : no_environment_)}));
    const bool shadow = shadowed(c), tint = tinted(c);
    c.encoder.set_bind_group(
        2, c.bind_group(p, {bind(shader::shadow_depth, shadow ? c.view(t_.shadow_map) : textures_->white()),
                            bind(shader::shadow_sampler, nearest), bind(shader::shadow, shadow ? c.buffer(t_.light_view) : no_shadow_view_),
                            bind(shader::translucent_shadow, tint ? c.view(t_.translucent_shadow) : textures_->white()),
                            bind(shader::translucent_shadow_depth, tint ? c.view(t_.translucent_shadow_depth) : textures_->white())}));
    const bool fog = fogged(c), air = aired(c);
    c.encoder.set_bind_group(3, c.bind_group(p, {bind(shader::fog, fog ? c.buffer(t_.fog_frame) : no_fog_frame_),
                                                 bind(shader::integrated_scattering, fog ? c.view(t_.integrated_scattering) : no_volume_),
                                                 bind(shader::integrated_transmittance, fog ? c.view(t_.integrated_transmittance) : no_volume_),
                                                 bind(shader::trilinear, c.sampler(rhi::StockSampler::trilinear_clamp)),
                                                 bind(shader::air, air ? c.buffer(t_.aerial_lookup) : no_aerial_lookup_),
                                                 bind(shader::aerial_scattering, air ? c.view(t_.aerial_scattering) : no_volume_),
                                                 bind(shader::aerial_transmittance, air ? c.view(t_.aerial_transmittance) : no_volume_)}));
  }

  // The translucent objects from the farthest to the nearest (their bounds' centres).
  std::vector<const plumbing::GpuObject*> back_to_front(const Scene& scene) const {
    std::vector<const plumbing::GpuObject*> order;
    for (const plumbing::GpuObject& o : geometry_->objects()) {
      if (o.translucent) order.push_back(&o);
    }
    const auto distance = [&](const plumbing::GpuObject* o) {
      const Vec3 d = physics::sub(o->center, scene.camera.position);
      return physics::dot(d, d);
    };
    std::stable_sort(order.begin(), order.end(), [&](auto* a, auto* b) { return distance(a) > distance(b); });
    return order;
  }

  void draw_solid_back_faces(PassContext& c) {
    c.encoder.set_pipeline(programs_.back_depth.pipeline);
    bind_surface_sets(c, textures_->white(), textures_->white(), textures_->white());
    for (const plumbing::GpuObject& o : geometry_->objects()) {
      if (o.translucent && o.volume == VolumeKind::solid) plumbing::SceneGeometry::draw(c.encoder, 1, o);
    }
  }

  // depth_peeling's first step: nothing is peeled yet, every surface lies in front of back_depth.
  void record_back_faces(PassContext& c) {
    write_block(c);
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.depth = {c.view(t_.back_depth), rhi::LoadOp::clear, 1.0f, false};
    pass.colors = {{c.view(t_.back_distance), rhi::LoadOp::clear, {0, 0, 0, 0}}};
    c.encoder.begin_render_pass(pass);
    if (!c.variant_is(t_.depth_peeling)) draw_solid_back_faces(c);
    c.encoder.end_render_pass();
  }

  // Layer k's depth: the farthest translucent surface in front of the opaque one and the layer before.
  void record_peel_depth(PassContext& c, size_t k) {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.depth = {c.view(t_.layer_depth(k)), rhi::LoadOp::clear, 0.0f, false};
    pass.colors = {{c.view(t_.layer_distance(k)), rhi::LoadOp::clear, {0, 0, 0, 0}}};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(programs_.peel_depth.pipeline);
    bind_surface_sets(c, c.view(t_.behind_layer(k)), textures_->white(), textures_->white());
    for (const plumbing::GpuObject& o : geometry_->objects()) {
      if (o.translucent) plumbing::SceneGeometry::draw(c.encoder, 1, o);
    }
    c.encoder.end_render_pass();
  }

  // Layer k's surfaces over what lies behind them: one fragment a pixel passes the equal test.
  void record_peel_shade(PassContext& c, size_t k) {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color), rhi::LoadOp::load}};
    pass.depth = {c.view(t_.layer_depth(k)), rhi::LoadOp::load, 0.0f, true};
    c.encoder.begin_render_pass(pass);
    bind_surface_sets(c, c.view(t_.behind_layer(k)), c.view(t_.behind_distance(k)),
                      refracting(c) ? c.view(t_.refracted_color) : textures_->white());
    const SurfacePrograms& p = programs_;
    for (const plumbing::GpuObject& o : geometry_->objects()) {
      if (!o.translucent) continue;
      if (o.volume != VolumeKind::solid) {
        draw_layer(c, o, {p.peel_transmittance_all, p.peel_radiance_all, p.peel_layer_all}, true);
        continue;
      }
      if (refracting(c)) {
        draw_layer(c, o, {p.peel_refract_front, p.peel_radiance_front, none_}, true);
      } else {
        draw_layer(c, o, {p.peel_transmittance_front, p.peel_radiance_front, p.peel_layer_front}, true);
      }
    }
    c.encoder.end_render_pass();
  }

  void record_sorted(PassContext& c) {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    bind_surface_sets(c, c.view(t_.back_depth), c.view(t_.back_distance), refracting(c) ? c.view(t_.refracted_color) : textures_->white());
    const SurfacePrograms& p = programs_;
    for (const plumbing::GpuObject* o : back_to_front(*c.scene)) {
      // A solid is seen through its front faces (its inside path reaches the back ones).
      if (o->volume != VolumeKind::solid) draw_layer(c, *o, {p.transmittance_back, p.radiance_back, p.layer_back}, o->convex);
      // A refracting solid's first draw replaces the colour: it stays two draws.
      const bool refracts = refracting(c) && o->volume == VolumeKind::solid;
      draw_layer(c, *o, refracts ? LayerPrograms{p.refract_front, p.radiance_front, none_}
                                 : LayerPrograms{p.transmittance_front, p.radiance_front, p.layer_front},
                 o->convex);
    }
    c.encoder.end_render_pass();
  }

  // One draw blends an object's own overlapping fragments in primitive order, two draw
  // them as sorted always has (every × T, then every + L): sorted draws once only a convex
  // object (at most one fragment a pixel a face set: `once_a_pixel`), so that both give
  // the same image; a peeled layer has one fragment a pixel (its depth test is equal).
  static void draw_layer(PassContext& c, const plumbing::GpuObject& o, const LayerPrograms& layer, bool once_a_pixel) {
    if (layer.combined.pipeline && once_a_pixel) {
      c.encoder.set_pipeline(layer.combined.pipeline);
      plumbing::SceneGeometry::draw(c.encoder, 1, o);
      return;
    }
    for (const plumbing::RenderProgram* program : {&layer.attenuate, &layer.add}) {
      c.encoder.set_pipeline(program->pipeline);
      plumbing::SceneGeometry::draw(c.encoder, 1, o);
    }
  }

  void record_accumulate(PassContext& c) {
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.oit_accumulation), rhi::LoadOp::clear, {0, 0, 0, 0}}, {c.view(t_.oit_optical_depth), rhi::LoadOp::clear, {0, 0, 0, 0}}};
    c.encoder.begin_render_pass(pass);
    bind_surface_sets(c, c.view(t_.back_depth), c.view(t_.back_distance), textures_->white());
    for (const plumbing::GpuObject& o : geometry_->objects()) {
      if (!o.translucent) continue;
      c.encoder.set_pipeline(o.volume == VolumeKind::solid ? programs_.accumulate_front.pipeline : programs_.accumulate_all.pipeline);
      plumbing::SceneGeometry::draw(c.encoder, 1, o);
    }
    c.encoder.end_render_pass();
  }

  void record_resolve(PassContext& c) {
    namespace shader = translucency_resolve_shader;
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.color), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    for (const plumbing::RenderProgram* p : {&resolve_[0], &resolve_[1]}) {
      c.encoder.set_pipeline(p->pipeline);
      c.encoder.set_bind_group(0, c.bind_group(*p, {bind(shader::oit_accumulation, c.view(t_.oit_accumulation)),
                                                    bind(shader::oit_optical_depth, c.view(t_.oit_optical_depth)),
                                                    bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp))}));
      c.encoder.draw(3);  // fullscreen.vert's one triangle
    }
    c.encoder.end_render_pass();
  }

  const TranslucencyTable& t_;
  SurfacePrograms programs_;
  const plumbing::RenderProgram none_{};  // no pipeline: a layer drawn twice
  std::array<plumbing::RenderProgram, 2> resolve_;
  rhi::BufferId block_, no_shadow_view_, no_fog_frame_, no_aerial_lookup_;
  rhi::TextureId no_volume_texture_, no_environment_texture_;
  rhi::TextureViewId no_volume_, no_environment_;
  std::unique_ptr<plumbing::SceneGeometry> geometry_;
  std::unique_ptr<plumbing::TextureCache> textures_;
  plumbing::SceneLighting lighting_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(TranslucencyTable, TranslucencyExecution);

}  // namespace volgraph
