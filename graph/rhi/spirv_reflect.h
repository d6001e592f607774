// SPIR-V reflection: the bind group layouts, the compute workgroup size and the uniform
// block layouts a pass's shaders declare, read from their SPIR-V (with SPIRV-Cross), so
// that the C++ need not repeat the GLSL; and a check that a host struct matches a block.
// Only what DESIGN.md's "Shaders that serve both backends" allows is accepted.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "graph/rhi/rhi.h"

namespace volgraph::rhi {

// One stage of a pipeline: its SPIR-V words and the shader_stage:: bit it runs as.
struct ShaderStageCode {
  std::span<const uint32_t> spirv;
  uint32_t stage = 0;
};

// The bind group layouts the stages declare: set i at index i, up to the highest set
// declared (a set none of them declares: no entries), entries sorted by binding, each
// visible to the stages that declare it. Layout i is labelled "<label> set <i>".
// Sampled textures and samplers are `filtered` when some instruction samples through them
// (OpImageSample*, gathers, OpImageQueryLod), not when they are only fetched or queried;
// storage textures take their access from NonWritable / NonReadable.
// Throws std::runtime_error for malformed SPIR-V, a stage whose entry point is not the
// stage given, two declarations of one binding that differ (naming the set, the binding
// and both stages), and what the rhi interface cannot express: arrays of resources,
// combined image samplers, push constants, sets beyond 3, cube / arrayed / multisampled
// images, and storage textures whose format is not a storage format of both backends.
std::vector<BindGroupLayoutDesc> reflect_bind_group_layouts(std::span<const ShaderStageCode> stages,
                                                            std::string_view label);

// The compute shader's workgroup size (its LocalSize execution mode): {x, y, z}.
// Throws std::runtime_error for malformed SPIR-V or a module without a literal LocalSize
// (none, or one given by specialisation constants).
std::array<uint32_t, 3> reflect_workgroup_size(std::span<const uint32_t> spirv);

// One top-level member of a uniform block: its name (or "member <i>" where the SPIR-V has
// no names), its byte offset from the block's start and its declared size in bytes (a
// struct or array member is one member, its size the whole struct's or array's).
struct UniformMember {
  std::string name;
  uint64_t offset = 0;
  uint64_t size = 0;
};

// A uniform buffer's block as the SPIR-V lays it out (its Offset decorations: std140 for
// glslang's uniform blocks): its set and binding, the block's name (the GLSL block name,
// "Params" in `uniform Params { … } params;`), its declared size in bytes (the end of its
// last member, not rounded up) and its members in declaration order.
struct UniformBlockLayout {
  uint32_t set = 0;
  uint32_t binding = 0;
  std::string name;
  uint64_t size = 0;
  std::vector<UniformMember> members;
};

// The uniform blocks the stages declare, sorted by set, then binding; a block declared by
// several stages appears once. Throws std::runtime_error for malformed SPIR-V, a stage whose
// entry point is not the stage given, a block without DescriptorSet and Binding, in a set
// beyond 3 or in an array, and two stages laying out one binding's block differently
// (naming the set, the binding and both stages). Messages but malformed SPIR-V's start with `label`.
std::vector<UniformBlockLayout> reflect_uniform_blocks(std::span<const ShaderStageCode> stages, std::string_view label);

// Checks a host (C++) struct named host_name against the uniform block it fills: host_size
// is its sizeof, host_offsets the offsetof of each of its members in declaration order, one
// per block member. Throws std::runtime_error with one message naming the host struct and
// the block (and its set and binding) when the member counts differ, when a member's offset
// differs (the first such, by the block's member name, with its size and both offsets), or
// when the sizes differ. The sizes must be equal exactly: a host struct padded beyond the
// block's declared size (to 16 bytes, say) is a mismatch too, so that uploading sizeof(host)
// bytes writes exactly the block.
void check_uniform_block(const UniformBlockLayout& block, uint64_t host_size, std::span<const uint64_t> host_offsets,
                         std::string_view host_name);

}  // namespace volgraph::rhi
