// Bind groups by shader variable name (graph/rhi/bind_by_name.h) on a production shader's
// reflected layouts and its generated names (shaders/bindings/): the set is the one the
// entries name; entries from two sets, a binding left out, one the layout lacks and one
// bound twice throw, naming the pass, the shader and the variable.
#include "graph/rhi/bind_by_name.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "graph/rhi/spirv_reflect.h"
#include "shaders/bindings/froxel_scatter_shadowed.comp.h"
#include "shaders/shader_library.h"

namespace volgraph::rhi {
namespace {

namespace shader = shaders::froxel_scatter_shadowed_comp;

// The generated names carry the GLSL's set and binding (froxel_scatter_shadowed.comp).
static_assert(shader::shadow_depth.set == 1 && shader::shadow_depth.binding == 0);
static_assert(shader::shadow.set == 1 && shader::shadow.binding == 2);
static_assert(shader::params.set == 0 && shader::params.binding == 5);

std::vector<BindGroupLayoutDesc> layouts() {
  const ShaderStageCode stage{shader_spirv("froxel_scatter_shadowed.comp"), shader_stage::compute};
  return reflect_bind_group_layouts({&stage, 1}, "froxel_scatter_shadowed.comp");
}

// The check's message, "" when it passes.
std::string failure(const std::vector<BoundResource>& resources) {
  try {
    check_bound_set(resources, layouts(), "fog", "froxel_scatter_shadowed.comp");
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

BoundResource shadow_depth() { return bind(shader::shadow_depth, TextureViewId{1}); }
BoundResource shadow_sampler() { return bind(shader::shadow_sampler, SamplerId{2}); }
BoundResource shadow_block() { return bind(shader::shadow, BufferId{3}); }

TEST(BindByName, TheSetIsTheOneTheEntriesNameInAnyOrder) {
  const std::vector<BoundResource> resources = {shadow_block(), shadow_depth(), shadow_sampler()};
  EXPECT_EQ(check_bound_set(resources, layouts(), "fog", "froxel_scatter_shadowed.comp"), 1u);
  const std::vector<BindGroupEntry> entries = entries_of(resources);
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].binding, 2u);
  EXPECT_EQ(entries[0].buffer.id, 3u);
}

TEST(BindByName, EntriesFromTwoSetsThrowNamingBoth) {
  const std::string message = failure({shadow_depth(), shadow_sampler(), shadow_block(), bind(shader::params, BufferId{4})});
  EXPECT_NE(message.find("pass fog"), std::string::npos) << message;
  EXPECT_NE(message.find("froxel_scatter_shadowed.comp"), std::string::npos) << message;
  EXPECT_NE(message.find("'shadow_depth' (set 1, binding 0)"), std::string::npos) << message;
  EXPECT_NE(message.find("'params' (set 0, binding 5)"), std::string::npos) << message;
}

TEST(BindByName, ABindingLeftOutThrows) {
  const std::string message = failure({shadow_depth(), shadow_block()});
  EXPECT_NE(message.find("leaves binding 1 unbound"), std::string::npos) << message;
  EXPECT_NE(message.find("shadow_depth, shadow"), std::string::npos) << message;
}

TEST(BindByName, ABindingTheLayoutLacksThrows) {
  const std::string message = failure({shadow_depth(), shadow_sampler(), shadow_block(), bind(ShaderBinding{1, 7, "stray"}, BufferId{5})});
  EXPECT_NE(message.find("'stray' (set 1, binding 7) is not in the shader's layout"), std::string::npos) << message;
}

TEST(BindByName, ABindingBoundTwiceThrows) {
  const std::string message = failure({shadow_depth(), shadow_sampler(), shadow_block(), shadow_block()});
  EXPECT_NE(message.find("binds 'shadow' (set 1, binding 2) twice"), std::string::npos) << message;
}

TEST(BindByName, NoEntriesThrow) { EXPECT_NE(failure({}).find("has no entries"), std::string::npos); }

}  // namespace
}  // namespace volgraph::rhi
