// Sizes at compile time: a config loaded once and resized (graph/graph.h resize()) gives
// every resource the extent loading it at that size gives, and the same plan memory, for
// every shipped config and a few sizes (odd ones included: rounding of divided sizes).
#include <filesystem>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> shipped_configs() {
  std::vector<std::string> out;
  for (const char* dir : {"configs", "configs/tests"}) {
    for (const auto& e : fs::directory_iterator(fs::path(::volgraph::testing::source_dir()) / dir)) {
      if (e.path().extension() == ".json") out.push_back(e.path().string());
    }
  }
  return out;
}

TEST(Resize, ResizedGraphsEqualGraphsLoadedAtThatSize) {
  PassRegistry registry;
  register_builtin_passes(registry);
  const std::vector<std::string> configs = shipped_configs();
  ASSERT_GT(configs.size(), 10u);
  for (const std::string& path : configs) {
    LoadedConfig once = load_config(path, registry);
    for (const Extent size : {Extent{320, 180, 1}, Extent{97, 61, 1}, Extent{1920, 1080, 1}}) {
      Overrides o;
      o.size = size;
      const LoadedConfig direct = load_config(path, registry, o);
      resize(once.graph, size);
      ASSERT_EQ(once.graph.resources.size(), direct.graph.resources.size()) << path;
      for (size_t r = 0; r < direct.graph.resources.size(); ++r) {
        const ResourceDesc& a = once.graph.resources[r].desc;
        const ResourceDesc& b = direct.graph.resources[r].desc;
        EXPECT_EQ(a.extent, b.extent) << path << ": " << b.name << " at " << size.width << "x" << size.height;
        EXPECT_EQ(a.buffer_bytes, b.buffer_bytes) << path << ": " << b.name;
      }
      EXPECT_EQ(compile(once.graph).memory.aliased_bytes, compile(direct.graph).memory.aliased_bytes) << path;
    }
  }
}

TEST(Resize, ChangesTheFrameSizedResources) {
  PassRegistry registry;
  register_builtin_passes(registry);
  LoadedConfig config = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/demo_fog.json", registry);
  const uint64_t before = compile(config.graph).memory.unaliased_bytes;
  resize(config.graph, {2 * config.graph.output_size.width, 2 * config.graph.output_size.height, 1});
  EXPECT_GT(compile(config.graph).memory.unaliased_bytes, 2 * before);
}

}  // namespace
}  // namespace volgraph
