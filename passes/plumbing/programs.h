// A pass's pipeline built from its shaders in shaders/, with the bind group layouts
// those shaders declare (SPIR-V reflection, graph/rhi/spirv_reflect.h): the C++ never
// restates a binding the GLSL already says. Bind groups are made by the shader's variable
// names: PassContext::bind_group(program, {rhi::bind(shaders::<shader>::<variable>, …), …}).
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "graph/rhi/rhi.h"
#include "graph/rhi/shader_binding.h"
#include "graph/rhi/spirv_reflect.h"

namespace volgraph::plumbing {

struct ComputeProgram {
  rhi::ComputePipelineId pipeline;
  std::vector<rhi::BindGroupLayoutId> layouts;  // set i at index i
  std::vector<rhi::BindGroupLayoutDesc> layout_descs;  // what each layout holds
  std::string shader;                                   // its file name, for messages
  std::vector<rhi::UniformBlockLayout> uniform_blocks;  // as the shader declares them (reflection)
  std::array<uint32_t, 3> workgroup_size{};
  // Workgroups covering `size` invocations per axis (one per texel).
  std::array<uint32_t, 3> groups_for(Extent size) const;
};

struct RenderProgram {
  rhi::RenderPipelineId pipeline;
  std::vector<rhi::BindGroupLayoutId> layouts;
  std::vector<rhi::UniformBlockLayout> uniform_blocks;
  std::vector<rhi::BindGroupLayoutDesc> layout_descs;  // what each layout holds
  std::string shader;                                   // "<vertex> + <fragment>", for messages
};

ComputeProgram create_compute_program(rhi::Device& device, const std::string& shader);

// `desc` gives the fixed-function state; its modules and layouts are filled in from the
// shaders (`fragment` empty: depth only).
RenderProgram create_render_program(rhi::Device& device, rhi::RenderPipelineDesc desc, const std::string& vertex,
                                    const std::string& fragment);
// A program that takes `layouts_of`'s bind group layouts, so the bind groups made for one
// serve both (the translucency passes' draws share the objects' groups; the shadow map's
// depth-only draws its masked draws'). Its shaders may use fewer bindings; those they
// declare must be in those layouts, of the same kind (throws std::logic_error otherwise).
RenderProgram create_render_program(rhi::Device& device, rhi::RenderPipelineDesc desc, const std::string& vertex,
                                    const std::string& fragment, const RenderProgram& layouts_of);

// One compute pass labelled `label`: the program's pipeline, `groups` bound at sets 0, 1, …
// (a null id leaves its set unbound) and one invocation per element of `invocations`.
void dispatch(rhi::CommandEncoder& encoder, const std::string& label, const ComputeProgram& program,
              std::initializer_list<rhi::BindGroupId> groups, Extent invocations);

// A uniform buffer holding `bytes` (a pass's parameter or frame block).
rhi::BufferId create_uniform_buffer(rhi::Device& device, const std::string& label, std::span<const std::byte> bytes);

// One holding a std140 block (a struct laid out as the shader's).
template <typename Block>
rhi::BufferId create_uniform_block(rhi::Device& device, const std::string& label, const Block& block) {
  return create_uniform_buffer(device, label, std::as_bytes(std::span(&block, 1)));
}

// The shader's uniform block at (set, binding); throws std::logic_error when it has none.
const rhi::UniformBlockLayout& uniform_block_at(const std::vector<rhi::UniformBlockLayout>& blocks, uint32_t set, uint32_t binding);

// A uniform buffer holding `block`, a C++ struct that mirrors the program's uniform block
// at (set, binding): checked against the reflected block first — the same size and every
// member at the same offset (`offsets`: offsetof each member of Block, in order) — so a
// struct that drifts from its GLSL fails when the pipeline is set up, naming the member.
template <typename Program, typename Block>
rhi::BufferId create_checked_uniform_block(rhi::Device& device, const Program& program, uint32_t set, uint32_t binding,
                                           const std::string& label, const Block& block, std::span<const uint64_t> offsets) {
  rhi::check_uniform_block(uniform_block_at(program.uniform_blocks, set, binding), sizeof(Block), offsets, label);
  return create_uniform_block(device, label, block);
}

// Mirror structs: a C++ struct laid out as a GLSL struct or uniform block (std140) lists
// its members' offsets in one place, `static constexpr std::array<uint64_t, N> offsets()`
// (offsetof each member, in declaration order), which every check of it uses.
// tests/unit/uniform_mirrors_test.cpp checks each against the shaders that declare it.

// Checks Block against the program's uniform block at (set, binding) whose members are
// Block's members (`uniform Params { ivec4 steps; vec4 distances; } params;`): the same
// size and every member at the same offset. Throws std::runtime_error naming `what` (the
// pass's buffer, "<pass> params") and the first member out of place (rhi::check_uniform_block);
// std::logic_error when the program has no block there. For blocks written every frame
// (encoder.update_buffer, device.write_buffer): call it at setup.
template <typename Block, typename Program>
void check_uniform_mirror(const Program& program, uint32_t set, uint32_t binding, std::string_view what) {
  static constexpr auto offsets = Block::offsets();
  rhi::check_uniform_block(uniform_block_at(program.uniform_blocks, set, binding), sizeof(Block), offsets, what);
}

// Checks Block against a uniform block at (set, binding) that holds one Block as its only
// member (`uniform Frame { FogFrame f; } frame;`): reflection sees one member, at offset 0,
// of the block's size — so sizeof(Block) is what is checked here (Block's own members are
// checked against the GLSL struct by the unit test).
template <typename Block, typename Program>
void check_wrapped_uniform_mirror(const Program& program, uint32_t set, uint32_t binding, std::string_view what) {
  static constexpr uint64_t offsets[] = {0};
  rhi::check_uniform_block(uniform_block_at(program.uniform_blocks, set, binding), sizeof(Block), offsets, what);
}

// The two checks at the uniform block the shader's variable names (its set and binding).
template <typename Block, typename Program>
void check_uniform_mirror(const Program& program, rhi::ShaderBinding block_variable, std::string_view what) {
  check_uniform_mirror<Block>(program, block_variable.set, block_variable.binding, what);
}
template <typename Block, typename Program>
void check_wrapped_uniform_mirror(const Program& program, rhi::ShaderBinding block_variable, std::string_view what) {
  check_wrapped_uniform_mirror<Block>(program, block_variable.set, block_variable.binding, what);
}

// create_checked_uniform_block with Block's own offsets list (Block::offsets()).
template <typename Program, typename Block>
rhi::BufferId create_checked_uniform_block(rhi::Device& device, const Program& program, uint32_t set, uint32_t binding,
                                           const std::string& label, const Block& block) {
  check_uniform_mirror<Block>(program, set, binding, label);
  return create_uniform_block(device, label, block);
}

// create_checked_uniform_block at the uniform block the shader's variable names
// (shaders/bindings/<shader>.h), so its set and binding are said once, in the GLSL.
template <typename Program, typename Block>
rhi::BufferId create_checked_uniform_block(rhi::Device& device, const Program& program, rhi::ShaderBinding block_variable,
                                           const std::string& label, const Block& block) {
  return create_checked_uniform_block(device, program, block_variable.set, block_variable.binding, label, block);
}

// A uniform block that holds one struct written once for GLSL and C++ (gpu_struct.h:
// `uniform VignetteBlock { VignetteParams params; };`): its layout was asserted at compile
// time by the shader's bindings header; here the program's block at the variable's set and
// binding is checked to be that one struct (one member, at 0, of its size), then made.
template <typename Program, typename Shared>
rhi::BufferId create_shared_uniform_block(rhi::Device& device, const Program& program, rhi::ShaderBinding block_variable,
                                          const std::string& label, const Shared& block) {
  static_assert(alignof(Shared) == 16, "a shared struct is declared with GPU_STRUCT (shaders/include/gpu_struct.h)");
  check_wrapped_uniform_mirror<Shared>(program, block_variable, label);
  return create_uniform_block(device, label, block);
}

}  // namespace volgraph::plumbing
