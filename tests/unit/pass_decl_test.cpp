// Pass declarations as `volgraph passes` prints them agree with the resources the loader
// binds: every slot's declared kind is the kind of every resource it is bound to in the
// shipped configs, output_like slots included (they take their source slot's kind). Step
// conditions: a pass type whose conditional step makes a slot that a step running more
// often uses is refused at registration, as is one whose first step is conditional; the
// loader adds only the steps whose condition holds (translucency's variants and layers).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

namespace fs = std::filesystem;

TEST(PassDecl, TwoSlotsOfOneNameAreRefusedAtRegistration) {
  PassDecl decl;
  decl.name = "twice";
  decl.variants.push_back({});
  decl.slots.push_back({});
  decl.slots.back().name = "color";
  decl.slots.push_back({});
  decl.slots.back().name = "color";
  decl.slots.back().direction = SlotDirection::output;
  PassRegistry registry;
  EXPECT_THROW(registry.add(decl), std::logic_error);
  decl.slots.back().name = "sky_color";
  EXPECT_NO_THROW(registry.add(decl));
}

// A size names its parameters by their handles (SizeSpec): a parameter's name, or a
// handle to a parameter of another type, does not compile.
template <typename Side>
concept SquareOfAccepts = requires(Side side) { SizeSpec::square_of(side); };
static_assert(SquareOfAccepts<ParamHandle<int64_t>>);
static_assert(!SquareOfAccepts<const char*>);
static_assert(!SquareOfAccepts<std::string>);
static_assert(!SquareOfAccepts<ParamHandle<double>>);

// A pass type whose outputs' sizes are its parameters: a volume of three, an image the
// frame divided by a choice's divisor. A number comes first, so no size parameter is index 0.
enum class Scale : uint8_t { one, quarter };
int64_t divisor_of(Scale s) { return s == Scale::quarter ? 4 : 1; }
struct SizedTable : PassTable {
  SizedTable() : PassTable("sized", PassKind::compute, "sizes from parameters") {}
  VariantHandle only = variant("only", "the one variant");
  ParamHandle<double> gain = number("gain", 1, 0, 2, "", "not a size");
  ParamHandle<int64_t> width = integer("width", 16, 1, 64, "texels", "x");
  ParamHandle<int64_t> height = integer("height", 8, 1, 64, "texels", "y");
  ParamHandle<int64_t> depth = integer("depth", 4, 1, 64, "texels", "z");
  ChoiceHandle<Scale> scale = choice("scale", Scale::one, {{Scale::one, "one"}, {Scale::quarter, "quarter"}}, "of the frame");
  SlotHandle volume = output("volume", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                             SizeSpec::volume_of(width, height, depth), "width × height × depth");
  SlotHandle image = output("image", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                            SizeSpec::of_output_divided_by_choice(scale, divisor_of), "the frame / scale");
};

// The extent of resource `name` in a graph of one sized pass with `params`, in a 64 × 32 frame.
Extent sized_extent(const std::string& name, const std::string& params) {
  PassRegistry registry;
  registry.add(SizedTable().decl);
  const std::string text = R"({ "output": { "size": [64, 32] },
  "graph": { "passes": [ { "name": "s", "type": "sized", "params": )" + params + R"( } ],
    "outputs": ["s.volume", "s.image"] } })";
  for (const GraphResource& r : load_config_text("sized.json", text, registry).graph.resources) {
    if (r.desc.name == name) return r.desc.extent;
  }
  ADD_FAILURE() << "no resource " << name;
  return {};
}

bool same(Extent a, Extent b) { return a.width == b.width && a.height == b.height && a.depth == b.depth; }

TEST(PassDecl, ASizeReadsTheParametersItsHandlesName) {
  EXPECT_TRUE(same(sized_extent("s.volume", "{}"), {16, 8, 4}));
  EXPECT_TRUE(same(sized_extent("s.volume", R"({ "width": 5, "height": 6, "depth": 7, "gain": 2 })"), {5, 6, 7}));
  EXPECT_TRUE(same(sized_extent("s.image", "{}"), {64, 32, 1}));
  EXPECT_TRUE(same(sized_extent("s.image", R"({ "scale": "quarter" })"), {16, 8, 1}));
}

// A scene check reads a parameter through its table's handle (param_in) and names it in
// its problem by the same handle (param_name), never by a second spelling.
TEST(PassDecl, AHandleReadsItsParameterAndNamesIt) {
  const SizedTable table;
  std::vector<ParamValue> values;
  for (const ParamDecl& param : table.decl.params) values.push_back(param.default_value);
  values[size_t(table.height.index)] = int64_t{12};
  EXPECT_EQ(param_in(values, table.height), 12);
  EXPECT_EQ(param_in(values, table.gain), 1.0);
  EXPECT_EQ(param_name(table.decl, table.height), "height");
  EXPECT_EQ(param_name(table.decl, table.scale.text), "scale");
}

// Registers `decl` in a registry of its own: whether it is refused.
bool refused_at_registration(const PassDecl& decl) {
  PassRegistry registry;
  try {
    registry.add(decl);
  } catch (const std::logic_error&) {
    return true;
  }
  return false;
}

TEST(PassDecl, ASizeOfAnotherTablesParametersIsRefusedAtRegistration) {
  const SizedTable table;
  PassDecl foreign = table.decl;
  foreign.params.resize(2);  // only "gain" and "width" left: the sizes read past the params
  EXPECT_TRUE(refused_at_registration(foreign));
  PassDecl retyped = table.decl;
  retyped.params[size_t(table.width.index)].type = ParamType::number;  // the size reads "width" as an integer
  EXPECT_TRUE(refused_at_registration(retyped));
  EXPECT_FALSE(refused_at_registration(table.decl));
}

// A pass type of steps: `made_by` makes an internal slot under its condition, `used_by` reads it under its own.
struct SteppedTable : PassTable {
  SteppedTable(StepCondition first, StepCondition made_by, StepCondition used_by)
      : PassTable("stepped", PassKind::graphics, "steps under conditions") {
    step("first", PassKind::graphics, {{target, Usage::color_attachment}}, std::move(first));
    step("make", PassKind::graphics, {{scratch, Usage::color_attachment}}, std::move(made_by));
    step("use", PassKind::graphics, {{target, Usage::color_attachment_load}, {scratch, Usage::sampled}}, std::move(used_by));
  }
  VariantHandle a = variant("a", "variant a");
  VariantHandle b = variant("b", "variant b");
  ParamHandle<int64_t> count = integer("count", 2, 1, 4, "", "how many");
  SlotHandle target = output("target", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float, SizeSpec::of_output(), "the image");
  SlotHandle scratch = internal("scratch", ResourceKind::texture2d, Format::rgba16_float, SizeSpec::of_output(), "in between");
};

bool refused(StepCondition first, StepCondition made_by, StepCondition used_by) {
  SteppedTable table(std::move(first), std::move(made_by), std::move(used_by));
  try {
    finish_steps(table.decl);
  } catch (const std::logic_error&) {
    return true;
  }
  return false;
}

TEST(PassDecl, AStepThatMakesASlotRunsWheneverItsUsersDo) {
  const SteppedTable t({}, {}, {});  // its handles' indices
  EXPECT_FALSE(refused({}, {}, {}));
  EXPECT_FALSE(refused({}, StepCondition{{t.a.index}}, StepCondition{{t.a.index}}));
  EXPECT_FALSE(refused({}, StepCondition{{t.a.index, t.b.index}}, StepCondition{{t.b.index}}));
  EXPECT_FALSE(refused({}, StepCondition{{t.a.index}, t.count.index, 1}, StepCondition{{t.a.index}, t.count.index, 2}));
  EXPECT_TRUE(refused({}, StepCondition{{t.a.index}}, {}));                    // used in b, made only in a
  EXPECT_TRUE(refused({}, StepCondition{{t.a.index}}, StepCondition{{t.b.index}}));
  EXPECT_TRUE(refused({}, StepCondition{{t.a.index}, t.count.index, 2}, StepCondition{{t.a.index}, t.count.index, 1}));
  EXPECT_TRUE(refused({}, StepCondition{{}, t.count.index, 1}, StepCondition{{t.a.index}}));
  EXPECT_TRUE(refused(StepCondition{{t.a.index}}, {}, {}));  // the first step is the pass's own graph pass
}

// Two steps of variants that never run together may each make one output (voxelize's
// overlap and fill): both are its maker, unless the second reads what it writes.
struct AlternativeMakersTable : PassTable {
  explicit AlternativeMakersTable(Usage second_usage, bool overlapping)
      : PassTable("alternatives", PassKind::graphics, "an output made by either variant's step") {
    step("first", PassKind::graphics, {{scratch, Usage::color_attachment}});
    step("in_a", PassKind::graphics, {{result, Usage::color_attachment}}, only_in({a}));
    step("in_b", PassKind::graphics, {{result, second_usage}}, overlapping ? only_in({a, b}) : only_in({b}));
  }
  VariantHandle a = variant("a", "variant a");
  VariantHandle b = variant("b", "variant b");
  SlotHandle result = output("result", ResourceKind::texture2d, Usage::color_attachment, Format::rgba16_float, SizeSpec::of_output(), "the image");
  SlotHandle scratch = internal("scratch", ResourceKind::texture2d, Format::rgba16_float, SizeSpec::of_output(), "in between");
};

TEST(PassDecl, StepsOfVariantsThatNeverRunTogetherEachMakeAnOutput) {
  AlternativeMakersTable table(Usage::color_attachment, false);
  finish_steps(table.decl);
  EXPECT_EQ(table.decl.steps[1].decl->slots[table.result.index].direction, SlotDirection::output);
  EXPECT_EQ(table.decl.steps[2].decl->slots[table.result.index].direction, SlotDirection::output);
  AlternativeMakersTable reads(Usage::color_attachment_load, false);  // b would read what a never wrote
  EXPECT_THROW(finish_steps(reads.decl), std::logic_error);
  AlternativeMakersTable overlapping(Usage::color_attachment, true);  // in a, the second step modifies the first's
  EXPECT_THROW(finish_steps(overlapping.decl), std::logic_error);
}

TEST(PassDecl, AConditionHoldsInItsVariantsWhileItsCountExceedsItsBound) {
  const SteppedTable t({}, {}, {});
  const StepCondition in_a_past_two{{t.a.index}, t.count.index, 2};
  EXPECT_TRUE(in_a_past_two.holds(t.a.index, {int64_t(3)}));
  EXPECT_FALSE(in_a_past_two.holds(t.a.index, {int64_t(2)}));
  EXPECT_FALSE(in_a_past_two.holds(t.b.index, {int64_t(3)}));
  EXPECT_TRUE(StepCondition{}.holds(t.b.index, {int64_t(0)}));
  EXPECT_TRUE(StepCondition{}.always());
  EXPECT_FALSE(in_a_past_two.always());
}

// The graph passes the loader makes of a translucency pass in `variant` with `params`.
std::vector<std::string> translucency_steps(const std::string& variant, const std::string& params) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const std::string text = R"({ "output": { "size": [8, 8] },
  "scene": { "camera": { "position": [0, 0, 3], "target": [0, 0, 0] },
             "materials": { "veil": { "albedo": [1, 1, 1], "alpha": 0.5 } },
             "objects": [ { "shape": "plane", "material": "veil", "transform": { "rotate_deg": [90, 0, 0] } } ] },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "glass", "type": "translucency", "variant": ")" + variant + R"(", "params": )" + params + R"(,
      "inputs": { "color": "lit.color", "depth": "lit.depth", "frame": "lit.frame" } } ],
    "outputs": ["glass.color"] } })";
  std::vector<std::string> names;
  for (const GraphPass& p : load_config_text("steps.json", text, registry).graph.passes) {
    if (p.name.rfind("glass", 0) == 0) names.push_back(p.name);
  }
  return names;
}

TEST(PassDecl, TheLoaderAddsOnlyTheStepsWhoseConditionHolds) {
  using Names = std::vector<std::string>;
  EXPECT_EQ(translucency_steps("sorted", "{}"), (Names{"glass/back_faces", "glass/surfaces"}));
  EXPECT_EQ(translucency_steps("weighted_oit", "{}"), (Names{"glass/back_faces", "glass/accumulate", "glass/resolve"}));
  EXPECT_EQ(translucency_steps("depth_peeling", R"({ "layers": 2 })"),
            (Names{"glass/back_faces", "glass/peel_depth_0", "glass/peel_shade_0", "glass/peel_depth_1", "glass/peel_shade_1"}));
  EXPECT_EQ(translucency_steps("depth_peeling", "{}").size(), 1u + 2 * 8);  // the default: 8 layers
}

// The registrations the tree's pass files make: "VOLGRAPH_REGISTER_PASS(" at a line's start.
size_t registrations_in_tree() {
  size_t count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(::volgraph::testing::source_dir()) + "/passes")) {
    if (entry.path().extension() != ".cpp") continue;
    std::ifstream file(entry.path());
    for (std::string line; std::getline(file, line);) count += line.rfind("VOLGRAPH_REGISTER_PASS(", 0) == 0 ? 1 : 0;
  }
  return count;
}

// Each pass file registers its pass type (VOLGRAPH_REGISTER_PASS), none dropped by the
// linker, in order of their names: listings and messages do not follow the link order.
TEST(PassDecl, BuiltinPassTypesRegisterThemselvesInOrderOfTheirNames) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const std::vector<std::string> names = registry.names();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(names.size(), registrations_in_tree()) << "every file's registration, none dropped by the linker";
  EXPECT_GE(names.size(), 28u);
  for (const char* name : {"clear", "copy", "vignette", "raymarch_fog", "atmosphere_bruneton_tables", "translucency", "scene"}) {
    EXPECT_NE(registry.find(name), nullptr) << name;
  }
}

TEST(PassDecl, OutputLikeSlotsHaveTheirSourcesKind) {
  PassRegistry registry;
  register_builtin_passes(registry);
  int like_slots = 0;
  for (const auto& decl : registry.all()) {
    for (const SlotDecl& s : decl->slots) {
      if (s.like.empty()) continue;
      ++like_slots;
      const SlotDecl& source = decl->slots.at(size_t(decl->slot_index(s.like)));
      EXPECT_EQ(int(s.kind), int(source.kind)) << decl->name << "." << s.name << " is like " << s.like;
    }
  }
  EXPECT_GE(like_slots, 3);  // froxel_scatter.in_scatter, froxel_temporal.accumulated, scatter_integrate.integrated_*
}

TEST(PassDecl, DeclaredKindsMatchTheBoundResourcesInEveryShippedConfig) {
  PassRegistry registry;
  register_builtin_passes(registry);
  int configs = 0;
  for (const char* dir : {"configs", "configs/tests"}) {
    for (const auto& e : fs::directory_iterator(fs::path(::volgraph::testing::source_dir()) / dir)) {
      if (e.path().extension() != ".json") continue;
      ++configs;
      const LoadedConfig config = load_config(e.path().string(), registry);
      for (const GraphPass& p : config.graph.passes) {
        for (const ResourceUse& u : p.uses) {
          const SlotDecl& slot = p.decl->slots.at(u.slot);
          EXPECT_EQ(int(slot.kind), int(config.graph.resources[u.resource].desc.kind))
              << e.path().filename().string() << ": " << p.name << "." << slot.name;
        }
      }
    }
  }
  EXPECT_GT(configs, 10);
}

}  // namespace
}  // namespace volgraph
