// A pass's pipeline built from its shaders in shaders/, with the bind group layouts
// those shaders declare (SPIR-V reflection, graph/rhi/spirv_reflect.h): the C++ never
// restates a binding the GLSL already says. Bind groups are made with `layouts[set]`.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "graph/rhi/rhi.h"

namespace volgraph::shading {

struct ComputeProgram {
  rhi::ComputePipelineId pipeline;
  std::vector<rhi::BindGroupLayoutId> layouts;  // set i at index i
  std::array<uint32_t, 3> workgroup_size{};
  // Workgroups covering `size` invocations per axis (one per texel).
  std::array<uint32_t, 3> groups_for(Extent size) const;
};

struct RenderProgram {
  rhi::RenderPipelineId pipeline;
  std::vector<rhi::BindGroupLayoutId> layouts;
  std::vector<rhi::BindGroupLayoutDesc> layout_descs;  // what each layout holds
};

ComputeProgram create_compute_program(rhi::Device& device, const std::string& shader);

// `desc` gives the fixed-function state; its modules and layouts are filled in from the
// shaders (`fragment` empty: depth only).
RenderProgram create_render_program(rhi::Device& device, rhi::RenderPipelineDesc desc, const std::string& vertex,
                                    const std::string& fragment);

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

}  // namespace volgraph::shading
