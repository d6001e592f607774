// The compiler on hand-made graphs whose plans are known: culling rules and their
// reasons, forwarding through culled inout passes, order, cycles, lifetimes,
// memory and barriers, and the debug switches.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "graph/config/config.h"
#include "graph/plan_report.h"
#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

constexpr auto k2D = ResourceKind::texture2d;

PassDecl make_decl(const char* name, PassKind kind, std::vector<SlotDecl> slots, SceneFeatures needs = 0) {
  PassDecl d;
  d.name = name;
  d.kind = kind;
  d.variants = {{"default", ""}};
  d.slots = std::move(slots);
  d.needs = needs;
  return d;
}

// A tiny frame: draw → fog_apply (modifies the colour, needs a medium) → tonemap.
struct Decls {
  PassDecl draw = make_decl("draw", PassKind::graphics,
                            {slot_out("color", k2D, Usage::color_attachment, Format::rgba16_float, SizeSpec::of_output(), "")});
  PassDecl fog_volume = make_decl("fog_volume", PassKind::compute,
                                  {slot_out("volume", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                                            SizeSpec::of_output(0.125f, 0.125f, 64), "")},
                                  feature_bit(SceneFeature::medium));
  PassDecl fog_apply = make_decl("fog_apply", PassKind::graphics,
                                 {slot_in("volume", ResourceKind::texture3d, Usage::sampled, ""),
                                  slot_inout("color", k2D, Usage::color_attachment_load, "")});
  PassDecl tonemap = make_decl("tonemap", PassKind::compute,
                               {slot_in("color", k2D, Usage::sampled, ""),
                                slot_out("output", k2D, Usage::storage_write, Format::rgba8_unorm, SizeSpec::of_output(), "")});
  PassDecl history = make_decl("history", PassKind::compute,
                               {slot_in("color", k2D, Usage::sampled, ""),
                                [] {
                                  SlotDecl s = slot_out("accumulated", k2D, Usage::storage_read_write, Format::rgba16_float,
                                                        SizeSpec::of_output(), "");
                                  s.persistent = true;
                                  return s;
                                }()});
};

struct FogFrame {
  Graph graph;
  uint32_t draw, volume, apply, tonemap;
};

FogFrame fog_frame(const Decls& d, SceneFeatures scene) {
  GraphBuilder b({64, 64, 1}, scene);
  FogFrame f;
  f.tonemap = b.add_pass("tonemap", d.tonemap);  // declared first: the order must come from the wiring
  f.apply = b.add_pass("apply", d.fog_apply);
  f.volume = b.add_pass("volume", d.fog_volume);
  f.draw = b.add_pass("draw", d.draw);
  const auto color = b.create(f.draw, 0, resolve_slot(d.draw, d.draw.slots[0], {64, 64, 1}, 0));
  const auto volume = b.create(f.volume, 0, resolve_slot(d.fog_volume, d.fog_volume.slots[0], {64, 64, 1}, 0));
  b.read(f.apply, 0, volume);
  const auto fogged = b.modify(f.apply, 1, color);
  b.read(f.tonemap, 0, fogged);
  b.mark_output(b.create(f.tonemap, 1, resolve_slot(d.tonemap, d.tonemap.slots[1], {64, 64, 1}, 0)));
  f.graph = b.finish();
  return f;
}

std::vector<std::string> order_names(const Graph& g, const Plan& p) {
  std::vector<std::string> out;
  for (const PlannedPass& pp : p.order) out.push_back(g.passes[pp.pass].name);
  return out;
}

TEST(Compiler, OrderFollowsWiringNotDeclaration) {
  Decls d;
  const FogFrame f = fog_frame(d, feature_bit(SceneFeature::medium));
  const Plan plan = compile(f.graph);
  // Ready passes run in declaration order: volume (declared 3rd) before draw (4th).
  EXPECT_EQ(order_names(f.graph, plan), (std::vector<std::string>{"volume", "draw", "apply", "tonemap"}));
  EXPECT_TRUE(plan.culled.empty());
}

TEST(Compiler, MissingMediumCullsFogAndForwardsTheColour) {
  Decls d;
  const FogFrame f = fog_frame(d, 0);
  const Plan plan = compile(f.graph);
  EXPECT_EQ(order_names(f.graph, plan), (std::vector<std::string>{"draw", "tonemap"}));
  ASSERT_EQ(plan.culled.size(), 2u);
  // Culled passes are listed in declaration order: apply (1), volume (2).
  EXPECT_EQ(plan.culled[0].pass, f.apply);
  EXPECT_EQ(plan.culled[0].reason, CullReason::input_culled);
  EXPECT_NE(cull_detail(f.graph, plan.culled[0]).find("volume"), std::string::npos);
  EXPECT_EQ(plan.culled[1].pass, f.volume);
  EXPECT_EQ(plan.culled[1].reason, CullReason::scene_lacks);
  EXPECT_EQ(cull_detail(f.graph, plan.culled[1]), "scene has no medium");
  // tonemap reads the colour draw made: one barrier, colour attachment → sampled.
  const PlannedPass& tm = plan.order[1];
  ASSERT_EQ(tm.barrier_count, 2u);  // the colour, and the output's first use
  const Barrier& b = plan.barriers[tm.barrier_begin];
  EXPECT_EQ(b.resource, 0u);
  EXPECT_EQ(b.from, (AccessState{stage::color_attachment_output, access::color_attachment_write, Layout::color_attachment}));
  EXPECT_EQ(b.to, (AccessState{stage::compute_shader, access::shader_sampled_read, Layout::shader_read_only}));
}

TEST(Compiler, NoCullKeepsEveryPassInTheSameRelativeOrder) {
  Decls d;
  const FogFrame f = fog_frame(d, 0);
  const Plan culled = compile(f.graph);
  const Plan all = compile(f.graph, {.cull = false});
  EXPECT_TRUE(all.culled.empty());
  EXPECT_EQ(all.order.size(), 4u);
  std::vector<std::string> kept;
  for (const std::string& name : order_names(f.graph, all)) {
    if (name == "draw" || name == "tonemap") kept.push_back(name);
  }
  EXPECT_EQ(kept, order_names(f.graph, culled));
}

TEST(Compiler, UnreachablePassIsCulledAsUnused) {
  Decls d;
  GraphBuilder b({8, 8, 1}, 0);
  const uint32_t a = b.add_pass("a", d.draw), side = b.add_pass("side", d.tonemap), out = b.add_pass("out", d.tonemap);
  const auto color = b.create(a, 0, resolve_slot(d.draw, d.draw.slots[0], {8, 8, 1}, 0));
  b.read(side, 0, color);
  b.create(side, 1, resolve_slot(d.tonemap, d.tonemap.slots[1], {8, 8, 1}, 0));
  b.read(out, 0, color);
  b.mark_output(b.create(out, 1, resolve_slot(d.tonemap, d.tonemap.slots[1], {8, 8, 1}, 0)));
  const Graph g = b.finish();
  const Plan plan = compile(g);
  ASSERT_EQ(plan.culled.size(), 1u);
  EXPECT_EQ(plan.culled[0].pass, side);
  EXPECT_EQ(plan.culled[0].reason, CullReason::unused);
  EXPECT_EQ(plan.lifetimes[1].first, kNone);  // side's output is never allocated
  EXPECT_EQ(plan.lifetimes[2].last, 2u);      // the graph output lives to the end of the frame
}

TEST(Compiler, WriteAfterReadCycleIsReportedWithItsPasses) {
  // c reads r before b modifies it, yet c also needs b's other output: b → c → b.
  Decls d;
  PassDecl modifier = make_decl("modifier", PassKind::graphics,
                                {slot_inout("color", k2D, Usage::color_attachment_load, ""),
                                 slot_out("extra", k2D, Usage::color_attachment, Format::rgba16_float, SizeSpec::of_output(), "")});
  PassDecl reader = make_decl("reader", PassKind::compute,
                              {slot_in("color", k2D, Usage::sampled, ""), slot_in("extra", k2D, Usage::sampled, ""),
                               slot_out("output", k2D, Usage::storage_write, Format::rgba8_unorm, SizeSpec::of_output(), "")});
  GraphBuilder b({8, 8, 1}, 0);
  const uint32_t a = b.add_pass("a", d.draw), pb = b.add_pass("b", modifier), pc = b.add_pass("c", reader);
  const auto r = b.create(a, 0, resolve_slot(d.draw, d.draw.slots[0], {8, 8, 1}, 0));
  b.modify(pb, 0, r);
  const auto extra = b.create(pb, 1, resolve_slot(modifier, modifier.slots[1], {8, 8, 1}, 0));
  b.read(pc, 0, r);
  b.read(pc, 1, extra);
  b.mark_output(b.create(pc, 2, resolve_slot(reader, reader.slots[2], {8, 8, 1}, 0)));
  const Graph g = b.finish();
  try {
    compile(g);
    FAIL() << "expected a cycle";
  } catch (const GraphError& e) {
    EXPECT_EQ(std::string(e.what()), "the graph has a cycle: b → c → b");
  }
}

TEST(Compiler, ModifyingAnOldVersionIsRejected) {
  Decls d;
  GraphBuilder b({8, 8, 1}, 0);
  const uint32_t a = b.add_pass("a", d.draw), x = b.add_pass("x", d.fog_apply), y = b.add_pass("y", d.fog_apply);
  const auto r = b.create(a, 0, resolve_slot(d.draw, d.draw.slots[0], {8, 8, 1}, 0));
  b.modify(x, 1, r);
  EXPECT_THROW(b.modify(y, 1, r), GraphError);
  EXPECT_THROW(b.mark_output(r), GraphError);  // overwritten later: not a valid output
}

TEST(Compiler, ReadingAndModifyingOneVersionInOnePassIsRejected) {
  Decls d;
  PassDecl both = make_decl("both", PassKind::graphics,
                            {slot_in("look", k2D, Usage::sampled, ""), slot_inout("color", k2D, Usage::color_attachment_load, "")});
  GraphBuilder b({8, 8, 1}, 0);
  const uint32_t a = b.add_pass("a", d.draw), m = b.add_pass("m", both);
  const auto r = b.create(a, 0, resolve_slot(d.draw, d.draw.slots[0], {8, 8, 1}, 0));
  b.read(m, 0, r);
  try {
    b.modify(m, 1, r);
    FAIL() << "expected a GraphError";
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("slots 'look' and 'color' both take 'a.color'"), std::string::npos) << e.what();
  }
}

TEST(Compiler, ReadsInOneLayoutShareOneBarrier) {
  // draw writes; two compute readers then a fragment reader sample it: one barrier
  // before the first reader covers all three stages.
  Decls d;
  PassDecl frag_reader = make_decl("frag_reader", PassKind::graphics,
                                   {slot_in("color", k2D, Usage::sampled, ""),
                                    slot_out("out", k2D, Usage::color_attachment, Format::rgba8_unorm, SizeSpec::of_output(), "")});
  GraphBuilder b({8, 8, 1}, 0);
  const uint32_t a = b.add_pass("a", d.draw);
  const uint32_t r1 = b.add_pass("r1", d.tonemap), r2 = b.add_pass("r2", d.tonemap), r3 = b.add_pass("r3", frag_reader);
  const auto color = b.create(a, 0, resolve_slot(d.draw, d.draw.slots[0], {8, 8, 1}, 0));
  for (uint32_t p : {r1, r2, r3}) {
    b.read(p, 0, color);
    const PassDecl& decl = *b.graph().passes[p].decl;
    b.mark_output(b.create(p, 1, resolve_slot(decl, decl.slots[1], {8, 8, 1}, 0)));
  }
  const Graph g = b.finish();
  const Plan plan = compile(g);
  int color_barriers = 0;
  for (const Barrier& br : plan.barriers) color_barriers += br.resource == 0;
  EXPECT_EQ(color_barriers, 2);  // undefined → colour attachment, then colour → read by all
  const Barrier& read = plan.barriers[plan.order[1].barrier_begin];
  EXPECT_EQ(read.resource, 0u);
  EXPECT_EQ(read.to.stages, stage::compute_shader | stage::vertex_shader | stage::fragment_shader);
}

TEST(Compiler, PersistentResourceIsNeverAliasedAndStartsAsItEnded) {
  Decls d;
  GraphBuilder b({8, 8, 1}, 0);
  const uint32_t a = b.add_pass("a", d.draw), h = b.add_pass("h", d.history);
  const auto color = b.create(a, 0, resolve_slot(d.draw, d.draw.slots[0], {8, 8, 1}, 0));
  b.read(h, 0, color);
  b.mark_output(b.create(h, 1, resolve_slot(d.history, d.history.slots[1], {8, 8, 1}, 0)));
  const Graph g = b.finish();
  const Plan plan = compile(g);
  EXPECT_EQ(plan.placements[1].heap, kNone);
  EXPECT_GT(plan.memory.persistent_bytes, 0u);
  // Frame N+1's read-write waits for frame N's read-write, in the general layout: no layout change.
  const Barrier& hb = plan.barriers[plan.order[1].barrier_begin + 1];
  EXPECT_EQ(hb.resource, 1u);
  EXPECT_EQ(hb.from.layout, Layout::general);
  EXPECT_EQ(hb.to.layout, Layout::general);
  EXPECT_EQ(hb.from.access, access::shader_storage_write);
}

TEST(Compiler, SerializeAddsOneFullBarrierBeforeEveryPassButTheFirst) {
  Decls d;
  const FogFrame f = fog_frame(d, feature_bit(SceneFeature::medium));
  const Plan plain = compile(f.graph);
  const Plan serial = compile(f.graph, {.serialize = true});
  EXPECT_EQ(serial.barriers.size(), plain.barriers.size() + plain.order.size() - 1);
  for (size_t i = 1; i < serial.order.size(); ++i) {
    const Barrier& g = serial.barriers[serial.order[i].barrier_begin];
    EXPECT_EQ(g.resource, kNone);
    EXPECT_EQ(g.from.stages, stage::all_commands);
  }
  EXPECT_EQ(serial.order.size(), plain.order.size());
}

TEST(Compiler, NoAliasGivesEveryResourceItsOwnBytes) {
  Decls d;
  const FogFrame f = fog_frame(d, feature_bit(SceneFeature::medium));
  const Plan plan = compile(f.graph, {.alias = false});
  EXPECT_TRUE(plan.handovers.empty());
  EXPECT_EQ(plan.memory.aliased_bytes, plan.memory.unaliased_bytes);
}

// needs_any: a pass culled only when the scene has none of its features (fog_apply
// composites a medium's images or the clouds', either suffices).
TEST(Compiler, NeedsAnyCullsOnlyWhenNoneOfItsFeaturesIsPresent) {
  Decls d;
  PassDecl apply = make_decl("apply", PassKind::graphics, {slot_inout("color", k2D, Usage::color_attachment_load, "")});
  apply.needs_any = feature_bit(SceneFeature::medium) | feature_bit(SceneFeature::clouds);
  const auto plan_for = [&](SceneFeatures scene) {
    GraphBuilder b({64, 64, 1}, scene);
    const uint32_t draw = b.add_pass("draw", d.draw);
    const uint32_t a = b.add_pass("apply", apply);
    const uint32_t tonemap = b.add_pass("tonemap", d.tonemap);
    const auto color = b.create(draw, 0, resolve_slot(d.draw, d.draw.slots[0], {64, 64, 1}, 0));
    b.read(tonemap, 0, b.modify(a, 0, color));
    b.mark_output(b.create(tonemap, 1, resolve_slot(d.tonemap, d.tonemap.slots[1], {64, 64, 1}, 0)));
    Graph g = b.finish();
    Plan p = compile(g);
    return std::pair{std::move(g), std::move(p)};
  };
  const std::vector<std::string> kept = {"draw", "apply", "tonemap"};
  for (const SceneFeatures scene : {feature_bit(SceneFeature::medium), feature_bit(SceneFeature::clouds),
                                    feature_bit(SceneFeature::medium) | feature_bit(SceneFeature::clouds)}) {
    const auto [g, plan] = plan_for(scene | feature_bit(SceneFeature::lights));
    EXPECT_EQ(order_names(g, plan), kept) << features_text(scene);
    EXPECT_TRUE(plan.culled.empty()) << features_text(scene);
  }
  const auto [g, plan] = plan_for(feature_bit(SceneFeature::lights) | feature_bit(SceneFeature::atmosphere));
  EXPECT_EQ(order_names(g, plan), (std::vector<std::string>{"draw", "tonemap"}));
  ASSERT_EQ(plan.culled.size(), 1u);
  EXPECT_EQ(plan.culled[0].reason, CullReason::scene_lacks);
  EXPECT_EQ(cull_detail(g, plan.culled[0]), "scene has no medium or clouds");
}

// The shipped configs, through the loader.
class ShippedConfigs : public ::testing::Test {
 protected:
  ShippedConfigs() { register_builtin_passes(registry_); }
  LoadedConfig load(const std::string& name) { return load_config(std::string(::volgraph::testing::source_dir()) + "/configs/" + name, registry_); }
  PassRegistry registry_;
};

TEST_F(ShippedConfigs, PointLightsCullTheShadowMapAndLeaveItsInputsUnbound) {
  const LoadedConfig c = load("demo_point_lights.json");
  const Plan plan = compile_loaded(c);
  ASSERT_EQ(plan.culled.size(), 1u);
  EXPECT_EQ(c.graph.passes[plan.culled[0].pass].name, "sun_shadow");
  EXPECT_EQ(plan.culled[0].reason, CullReason::scene_lacks);
  EXPECT_EQ(cull_detail(c.graph, plan.culled[0]), "scene has no shadow_casting_light");
  for (uint32_t r = 0; r < c.graph.resources.size(); ++r) {
    if (c.graph.resources[r].desc.name.rfind("sun_shadow.", 0) == 0) EXPECT_EQ(plan.lifetimes[r].first, kNone);
  }
}

// demo_clouds has clouds and no medium: fog_apply and pixel_temporal (needs: medium or
// clouds) still composite and average cloud_march's images.
TEST_F(ShippedConfigs, CloudsWithoutAMediumKeepFogApplyAndPixelTemporal) {
  const LoadedConfig c = load("demo_clouds.json");
  EXPECT_EQ(c.config.scene.features() & feature_bit(SceneFeature::medium), 0u) << "demo_clouds carries a medium again";
  const Plan plan = compile_loaded(c);
  EXPECT_TRUE(plan.culled.empty()) << cull_detail(c.graph, plan.culled[0]);
  EXPECT_EQ(order_names(c.graph, plan),
            (std::vector<std::string>{"lit", "noise", "clouds", "clouds_temporal", "apply", "final"}));
}

TEST_F(ShippedConfigs, UnusedUtilityPassesAreCulledAndAliasingSavesMemory) {
  const LoadedConfig c = load("refraction_copy.json");
  const Plan plan = compile_loaded(c);
  std::vector<std::string> culled;
  for (const CulledPass& cp : plan.culled) culled.push_back(c.graph.passes[cp.pass].name);
  EXPECT_EQ(culled, (std::vector<std::string>{"overlay", "debug_view"}));
  EXPECT_LT(plan.memory.aliased_bytes, plan.memory.unaliased_bytes);
  EXPECT_GE(plan.memory.aliased_bytes, plan.memory.lower_bound_bytes);
  EXPECT_FALSE(plan.handovers.empty());
}

TEST_F(ShippedConfigs, JsonReportCarriesTheMemoryFigures) {
  const LoadedConfig c = load("demo_primitives.json");
  const Plan plan = compile_loaded(c);
  const auto j = nlohmann::json::parse(plan_json(c.graph, plan));
  EXPECT_EQ(j["order"].size(), plan.order.size());
  EXPECT_EQ(j["memory"]["aliased_bytes"].get<uint64_t>(), plan.memory.aliased_bytes);
  EXPECT_EQ(j["memory"]["lower_bound_bytes"].get<uint64_t>(), plan.memory.lower_bound_bytes);
  EXPECT_EQ(j["order"][0]["pass"], "sun_shadow");
}

}  // namespace
}  // namespace volgraph

namespace volgraph {
namespace {

// Cubes are transients like any image: in the glass of water, the probe's mip chain takes
// over bytes an earlier transient used (a hand-over), and every cube's bytes are six faces'.
TEST_F(ShippedConfigs, CubeMapsAreAliasedAsAnyTransient) {
  const LoadedConfig c = load("demo_glass_of_water.json");
  const Plan plan = compile_loaded(c);
  bool cube_takes_over = false;
  for (const Handover& h : plan.handovers) {
    cube_takes_over |= c.graph.resources[h.resource].desc.kind == ResourceKind::texture_cube;
  }
  EXPECT_TRUE(cube_takes_over);
  for (const GraphResource& r : c.graph.resources) {
    if (r.desc.kind != ResourceKind::texture_cube) continue;
    ResourceDesc one_face = r.desc;
    one_face.kind = ResourceKind::texture2d;
    EXPECT_EQ(content_bytes(r.desc), 6 * content_bytes(one_face)) << r.desc.name;
  }
}

}  // namespace
}  // namespace volgraph
