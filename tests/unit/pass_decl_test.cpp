// Pass declarations as `volgraph passes` prints them agree with the resources the loader
// binds: every slot's declared kind is the kind of every resource it is bound to in the
// shipped configs, output_like slots included (they take their source slot's kind).
#include <filesystem>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"

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
    for (const auto& e : fs::directory_iterator(fs::path(VOLGRAPH_SOURCE_DIR) / dir)) {
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
