// A pass's pipeline built from its shaders in shaders/, with the bind group layouts
// those shaders declare (SPIR-V reflection, graph/rhi/spirv_reflect.h): the C++ never
// restates a binding the GLSL already says. Bind groups are made with `layouts[set]`.
#pragma once

#include <array>
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

}  // namespace volgraph::shading
