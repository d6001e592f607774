// SPIR-V reflection on the embedded production shaders (their layouts are the ones the
// passes write by hand today) and on test-only shaders (tests/unit/shaders/): storage
// textures and buffers (with their access), textures sampled through a sampler or only
// fetched, a conflict between stages, and what the rhi cannot express.
#include "graph/rhi/spirv_reflect.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shaders/shader_library.h"
#include "tests/unit/shaders/test_shaders.h"

namespace volgraph::rhi {
namespace {

using Layouts = std::vector<std::vector<std::string>>;  // per set, one line per entry

std::string binding_type_text(BindingType type) {
  switch (type) {
    case BindingType::uniform_buffer: return "uniform_buffer";
    case BindingType::storage_buffer: return "storage_buffer";
    case BindingType::read_only_storage_buffer: return "read_only_storage_buffer";
    case BindingType::sampled_texture: return "sampled_texture";
    case BindingType::sampler: return "sampler";
    case BindingType::storage_texture: return "storage_texture";
  }
  return "?";
}

std::string visibility_text(uint32_t visibility) {
  std::string text;
  if (visibility & shader_stage::vertex) text += "V";
  if (visibility & shader_stage::fragment) text += "F";
  if (visibility & shader_stage::compute) text += "C";
  return text;
}

std::string_view access_text(StorageAccess access) {
  switch (access) {
    case StorageAccess::read_only: return "read_only";
    case StorageAccess::write_only: return "write_only";
    case StorageAccess::read_write: break;
  }
  return "read_write";
}

// "2 C storage_texture texture2d rgba32_float write_only": binding, stages, type, then the
// texture kind (textures), format and access (storage textures), and for sampled
// textures and samplers whether a shader filters through them or only fetches.
std::string entry_text(const LayoutEntry& entry) {
  std::string text =
      std::to_string(entry.binding) + " " + visibility_text(entry.visibility) + " " + binding_type_text(entry.type);
  const bool is_texture = entry.type == BindingType::sampled_texture || entry.type == BindingType::storage_texture;
  if (is_texture) text += " " + std::string(kind_name(entry.texture_kind));
  if (entry.type == BindingType::storage_texture) {
    text += " " + std::string(format_info(entry.storage_format).name) + " " + std::string(access_text(entry.storage_access));
  }
  const bool samples = entry.type == BindingType::sampled_texture || entry.type == BindingType::sampler;
  if (samples) text += entry.filtered ? " filtered" : " fetched";
  return text;
}

Layouts layouts_text(const std::vector<BindGroupLayoutDesc>& layouts) {
  Layouts text;
  for (const BindGroupLayoutDesc& layout : layouts) {
    text.emplace_back();
    for (const LayoutEntry& entry : layout.entries) text.back().push_back(entry_text(entry));
  }
  return text;
}

std::vector<std::string> labels(const std::vector<BindGroupLayoutDesc>& layouts) {
  std::vector<std::string> names;
  for (const BindGroupLayoutDesc& layout : layouts) names.push_back(layout.label);
  return names;
}

std::span<const uint32_t> production(std::string_view name) {
  const std::span<const uint32_t> words = shader_spirv(name);
  EXPECT_FALSE(words.empty()) << name;
  return words;
}

std::span<const uint32_t> test_only(std::string_view name) {
  const std::span<const uint32_t> words = test_shader_spirv(name);
  EXPECT_FALSE(words.empty()) << name;
  return words;
}

std::vector<BindGroupLayoutDesc> reflect(std::vector<ShaderStageCode> stages, std::string_view label) {
  return reflect_bind_group_layouts(stages, label);
}

// The message reflection throws, or "" when it does not.
std::string reflection_error(std::vector<ShaderStageCode> stages, std::string_view label) {
  try {
    reflect_bind_group_layouts(stages, label);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST(SpirvReflect, CompositeDeclaresTextureSamplerStorageImageAndUniforms) {
  const auto layouts = reflect({{production("composite.comp"), shader_stage::compute}}, "composite");
  EXPECT_EQ(labels(layouts), (std::vector<std::string>{"composite set 0"}));
  EXPECT_EQ(layouts_text(layouts), (Layouts{{"0 C sampled_texture texture2d fetched", "1 C sampler fetched",
                                             "2 C storage_texture texture2d rgba32_float write_only", "3 C uniform_buffer"}}));
}

TEST(SpirvReflect, SceneStagesMergeVisibilityPerBinding) {
  const auto layouts = reflect(
      {{production("scene.vert"), shader_stage::vertex}, {production("scene_shadowed.frag"), shader_stage::fragment}},
      "scene");
  EXPECT_EQ(labels(layouts), (std::vector<std::string>{"scene set 0", "scene set 1", "scene set 2"}));
  const std::vector<std::string> object = {"0 VF uniform_buffer", "1 F sampled_texture texture2d filtered",
                                           "2 F sampled_texture texture2d filtered", "3 F sampler filtered"};  // block + material textures
  EXPECT_EQ(layouts_text(layouts), (Layouts{{"0 VF uniform_buffer"},
                                            object,
                                            {"0 F sampled_texture texture2d fetched", "1 F sampler fetched", "2 F uniform_buffer"}}));
}

// The opacity shadow map is sampled (trilinear) inside a function that takes the texture
// and the sampler as parameters: reflection follows the calls back to the variables;
// the shadow map, fetched in a function too, stays non-filtering.
TEST(SpirvReflect, SamplingThroughFunctionParametersFilters) {
  const auto layouts = reflect({{production("scene.vert"), shader_stage::vertex},
                                {production("scene_media_shadowed.frag"), shader_stage::fragment}},
                               "scene");
  ASSERT_EQ(layouts.size(), 3u);
  EXPECT_EQ(layouts_text(layouts)[2], (std::vector<std::string>{"0 F sampled_texture texture2d fetched", "1 F sampler fetched",
                                                                  "2 F uniform_buffer", "3 F sampled_texture texture3d filtered",
                                                                  "4 F sampler filtered"}));
}

TEST(SpirvReflect, UnshadowedSceneFragmentHasNoShadowSet) {
  const auto layouts = reflect(
      {{production("scene.vert"), shader_stage::vertex}, {production("scene.frag"), shader_stage::fragment}}, "scene");
  EXPECT_EQ(layouts_text(layouts), (Layouts{{"0 VF uniform_buffer"},
                                            {"0 VF uniform_buffer", "1 F sampled_texture texture2d filtered",
                                             "2 F sampled_texture texture2d filtered", "3 F sampler filtered"}}));
}

TEST(SpirvReflect, ShadowVertexDeclaresViewAndObject) {
  const auto layouts = reflect({{production("shadow.vert"), shader_stage::vertex}}, "shadow");
  EXPECT_EQ(layouts_text(layouts), (Layouts{{"0 V uniform_buffer"}, {"0 V uniform_buffer"}}));
}

TEST(SpirvReflect, ShaderWithoutBindingsHasNoLayouts) {
  EXPECT_TRUE(reflect({{production("flat_color.vert"), shader_stage::vertex}}, "flat").empty());
  EXPECT_TRUE(reflect({}, "nothing").empty());
}

TEST(SpirvReflect, StorageTexturesAndBuffers) {
  const auto layouts = reflect({{test_only("storage.comp"), shader_stage::compute}}, "storage");
  EXPECT_EQ(labels(layouts), (std::vector<std::string>{"storage set 0", "storage set 1", "storage set 2"}));
  EXPECT_EQ(layouts_text(layouts),
            (Layouts{{"0 C storage_texture texture3d rgba16_float write_only", "1 C storage_texture texture2d r32_float write_only",
                      "2 C read_only_storage_buffer", "3 C storage_texture texture2d r32_uint read_write"},
                     {},
                     {"0 C storage_buffer", "1 C storage_buffer", "2 C sampled_texture texture3d filtered", "3 C sampler filtered",
                      "4 C storage_texture texture2d rgba8_unorm write_only"}}));
}

TEST(SpirvReflect, WorkgroupSize) {
  EXPECT_EQ(reflect_workgroup_size(production("composite.comp")), (std::array<uint32_t, 3>{8, 8, 1}));
  EXPECT_EQ(reflect_workgroup_size(test_only("storage.comp")), (std::array<uint32_t, 3>{4, 2, 1}));
}

TEST(SpirvReflect, WorkgroupSizeOfAVertexShaderThrows) {
  EXPECT_THROW(reflect_workgroup_size(production("scene.vert")), std::runtime_error);
}

TEST(SpirvReflect, StagesDeclaringOneBindingDifferentlyThrow) {
  EXPECT_EQ(reflection_error({{test_only("conflict.vert"), shader_stage::vertex},
                              {test_only("conflict.frag"), shader_stage::fragment}},
                             "conflict"),
            "conflict: set 1, binding 2 declared differently: vertex shader: uniform buffer; fragment shader: "
            "sampled texture texture2d");
}

// What the rhi (and WebGPU) cannot express: one test shader each, one stage.
struct Rejected {
  std::string_view shader;
  uint32_t stage;
  std::string_view message;
};

TEST(SpirvReflect, WhatTheInterfaceCannotExpressIsRejected) {
  const Rejected cases[] = {
      {"texture_array.comp", shader_stage::compute,
       "t: compute shader: set 0, binding 1: arrays of resources are not supported: one resource per binding"},
      {"combined_sampler.frag", shader_stage::fragment,
       "t: fragment shader: set 0, binding 0: combined image samplers are not supported: declare a texture and a "
       "sampler"},
      {"push_constant.comp", shader_stage::compute,
       "t: compute shader: push constants are not supported: use a uniform buffer"},
      {"fifth_set.comp", shader_stage::compute, "t: compute shader: set 4, binding 0: at most 4 sets (0 to 3)"},
  };
  for (const Rejected& rejected : cases) {
    EXPECT_EQ(reflection_error({{test_only(rejected.shader), rejected.stage}}, "t"), rejected.message)
        << rejected.shader;
  }
}

TEST(SpirvReflect, StageThatIsNotTheEntryPointsThrows) {
  EXPECT_EQ(reflection_error({{production("scene.frag"), shader_stage::vertex}}, "scene"),
            "scene: vertex shader: the module has no entry point of that stage");
}

TEST(SpirvReflect, MalformedModulesThrow) {
  EXPECT_EQ(reflection_error({{{}, shader_stage::compute}}, "empty"),
            "SPIR-V: not a SPIR-V module (no header or magic number)");
  // The first instruction (word 5, after the header) claims more words than there are.
  const std::span<const uint32_t> composite = production("composite.comp");
  std::vector<uint32_t> overrun(composite.begin(), composite.end());
  overrun[5] = 0xffffu << 16 | (overrun[5] & 0xffffu);
  EXPECT_EQ(reflection_error({{overrun, shader_stage::compute}}, "overrun"), "SPIR-V: malformed instruction at word 5");
  EXPECT_THROW(reflect_workgroup_size(overrun), std::runtime_error);
}

}  // namespace
}  // namespace volgraph::rhi
