// SPIR-V reflection on the embedded production shaders (their layouts are the ones the
// passes write by hand today) and on test-only shaders (tests/unit/shaders/): storage
// textures and buffers (with their access), textures sampled through a sampler or only
// fetched, a conflict between stages, and what the rhi cannot express; uniform block
// layouts, and host structs checked against them.
#include "graph/rhi/spirv_reflect.h"

#include <gtest/gtest.h>

#include <cstddef>
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
  // Well framed, but a SPIR-V version SPIRV-Cross does not know (header word 1): its error.
  std::vector<uint32_t> unknown_version(composite.begin(), composite.end());
  unknown_version[1] = 0x7f0000;
  EXPECT_EQ(reflection_error({{unknown_version, shader_stage::compute}}, "version"), "SPIR-V: Invalid SPIRV format.");
}

TEST(SpirvReflect, WorkgroupSizeFromSpecialisationConstantsThrows) {
  try {
    reflect_workgroup_size(test_only("spec_workgroup.comp"));
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "SPIR-V: the workgroup size is given by specialisation constants (constant_id 0), not "
                               "literal sizes");
  }
}

// ---- Uniform block layouts ------------------------------------------------------------

// "CompositeParams set 0 binding 3, 16 bytes: size@0+8 exposure_ev@8+4 tone_map_op@12+4".
std::string block_text(const UniformBlockLayout& block) {
  std::string text = block.name + " set " + std::to_string(block.set) + " binding " + std::to_string(block.binding) +
                     ", " + std::to_string(block.size) + " bytes:";
  for (const UniformMember& member : block.members) {
    text += " " + member.name + "@" + std::to_string(member.offset) + "+" + std::to_string(member.size);
  }
  return text;
}

std::vector<std::string> blocks_text(std::vector<ShaderStageCode> stages) {
  std::vector<std::string> text;
  for (const UniformBlockLayout& block : reflect_uniform_blocks(stages, "t")) text.push_back(block_text(block));
  return text;
}

UniformBlockLayout only_block(std::vector<ShaderStageCode> stages, uint32_t set, uint32_t binding) {
  for (const UniformBlockLayout& block : reflect_uniform_blocks(stages, "t")) {
    if (block.set == set && block.binding == binding) return block;
  }
  ADD_FAILURE() << "no uniform block at set " << set << ", binding " << binding;
  return {};
}

// The message check_uniform_block throws, or "" when it does not.
std::string host_error(const UniformBlockLayout& block, uint64_t size, std::vector<uint64_t> offsets,
                       std::string_view name) {
  try {
    check_uniform_block(block, size, offsets, name);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST(SpirvReflect, CompositeParamsBlockLayout) {
  EXPECT_EQ(blocks_text({{test_only("inline_block.comp"), shader_stage::compute}}),
            (std::vector<std::string>{
                "CompositeParams set 0 binding 3, 16 bytes: size@0+8 exposure_ev@8+4 tone_map_op@12+4"}));
  // composite.comp holds the same members as one struct written once (gpu_struct.h).
  EXPECT_EQ(blocks_text({{production("composite.comp"), shader_stage::compute}}),
            (std::vector<std::string>{"CompositeParamsBlock set 0 binding 3, 16 bytes: params@0+16"}));
}

// froxel_scatter_body.glsl: the frame block (one FogFrame member) and the pass's Params.
TEST(SpirvReflect, FroxelScatterBlockLayouts) {
  const std::vector<ShaderStageCode> stages = {{production("froxel_scatter.comp"), shader_stage::compute}};
  const std::vector<UniformBlockLayout> blocks = reflect_uniform_blocks(stages, "t");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].name, "Frame");
  EXPECT_EQ(blocks[0].binding, 0u);
  ASSERT_EQ(blocks[0].members.size(), 1u);
  EXPECT_EQ(blocks[0].members[0].name, "f");
  EXPECT_EQ(blocks[0].members[0].offset, 0u);
  EXPECT_EQ(blocks[0].members[0].size, blocks[0].size);
  EXPECT_EQ(block_text(blocks[1]), "FroxelScatterParamsBlock set 0 binding 5, 48 bytes: params@0+48");
}

// Both scene stages declare the frame and object blocks: each is listed once.
TEST(SpirvReflect, SceneBlocksMergeAcrossStages) {
  const std::vector<std::string> blocks = blocks_text(
      {{production("scene.vert"), shader_stage::vertex}, {production("scene.frag"), shader_stage::fragment}});
  ASSERT_EQ(blocks.size(), 2u);
  // Both blocks hold one struct written once for GLSL and C++ (scene_frame.h, object_uniforms.h).
  EXPECT_EQ(blocks[0], "SceneFrameBlock set 0 binding 0, 2272 bytes: frame@0+2272");
  EXPECT_EQ(blocks[1], "ObjectUniformsBlock set 1 binding 0, 208 bytes: object@0+208");
}

TEST(SpirvReflect, Std140GapsAndPacking) {
  EXPECT_EQ(blocks_text({{test_only("uniform_layout.comp"), shader_stage::compute}}),
            (std::vector<std::string>{"Layout set 0 binding 0, 132 bytes: a@0+4 b@16+12 c@28+4 d@32+8 e@48+32 m@80+48 "
                                      "last@128+4"}));
}

TEST(SpirvReflect, StagesLayingOutOneBlockDifferentlyThrow) {
  try {
    reflect_uniform_blocks(std::vector<ShaderStageCode>{{test_only("conflict.vert"), shader_stage::vertex},
                                                        {test_only("block_conflict.frag"), shader_stage::fragment}},
                           "conflict");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "conflict: set 1, binding 2 declared differently: vertex shader: uniform block Scale "
                               "(16 bytes: factor at 0); fragment shader: uniform block Scale (32 bytes: bias at 0, "
                               "factor at 16)");
  }
}

// inline_block.comp's CompositeParams, as a host would write it.
struct CompositeParams {
  uint32_t size[2];
  float exposure_ev;
  int32_t tone_map_op;
};

TEST(SpirvReflect, MatchingHostStructPasses) {
  const UniformBlockLayout block = only_block({{test_only("inline_block.comp"), shader_stage::compute}}, 0, 3);
  const std::vector<uint64_t> offsets = {offsetof(CompositeParams, size), offsetof(CompositeParams, exposure_ev),
                                         offsetof(CompositeParams, tone_map_op)};
  EXPECT_NO_THROW(check_uniform_block(block, sizeof(CompositeParams), offsets, "CompositeParams"));
}

// A host struct with a member in the wrong place, then one of the wrong size, then one
// with a member too few.
TEST(SpirvReflect, MismatchedHostStructsAreCaught) {
  struct Misplaced {
    uint32_t size[2];
    float padding;  // pushes exposure_ev to 12
    float exposure_ev;
    int32_t tone_map_op;
  };
  struct alignas(32) Oversized {
    uint32_t size[2];
    float exposure_ev;
    int32_t tone_map_op;
  };
  const UniformBlockLayout block = only_block({{test_only("inline_block.comp"), shader_stage::compute}}, 0, 3);
  EXPECT_EQ(host_error(block, sizeof(Misplaced),
                       {offsetof(Misplaced, size), offsetof(Misplaced, exposure_ev), offsetof(Misplaced, tone_map_op)},
                       "Misplaced"),
            "host struct Misplaced does not match uniform block CompositeParams (set 0, binding 3): member 1 "
            "(exposure_ev, 4 bytes) is at offset 8 in the block, 12 in the host struct");
  EXPECT_EQ(host_error(block, sizeof(Oversized),
                       {offsetof(Oversized, size), offsetof(Oversized, exposure_ev), offsetof(Oversized, tone_map_op)},
                       "Oversized"),
            "host struct Oversized does not match uniform block CompositeParams (set 0, binding 3): the block is 16 "
            "bytes, the host struct 32 (the sizes must be equal)");
  EXPECT_EQ(host_error(block, 12, {0, 8}, "Short"),
            "host struct Short does not match uniform block CompositeParams (set 0, binding 3): the block has 3 "
            "members, the host struct 2");
}

// std140 needs padding a naively packed host struct lacks: the check finds the first
// member out of place; the padded struct matches.
TEST(SpirvReflect, Std140HostStructs) {
  struct Packed {
    float a;
    float b[3];  // at 4: std140 puts b at 16
    float c;
    float d[2];
    float e[2];
    float m[9];
    int32_t last;
  };
  struct Padded {
    float a;
    float pad0[3];
    float b[3];
    float c;
    float d[2];
    float pad1[2];
    float e[2][4];  // array stride 16
    float m[3][4];  // column stride 16
    int32_t last;
  };
  const UniformBlockLayout block = only_block({{test_only("uniform_layout.comp"), shader_stage::compute}}, 0, 0);
  EXPECT_EQ(host_error(block, sizeof(Packed),
                       {offsetof(Packed, a), offsetof(Packed, b), offsetof(Packed, c), offsetof(Packed, d),
                        offsetof(Packed, e), offsetof(Packed, m), offsetof(Packed, last)},
                       "Packed"),
            "host struct Packed does not match uniform block Layout (set 0, binding 0): member 1 (b, 12 bytes) is at "
            "offset 16 in the block, 4 in the host struct");
  EXPECT_EQ(host_error(block, sizeof(Padded),
                       {offsetof(Padded, a), offsetof(Padded, b), offsetof(Padded, c), offsetof(Padded, d),
                        offsetof(Padded, e), offsetof(Padded, m), offsetof(Padded, last)},
                       "Padded"),
            "");
}

}  // namespace
}  // namespace volgraph::rhi
