// SPIR-V reflection: the bind group layouts and the compute workgroup size a pass's
// shaders declare, read from their SPIR-V, so that the C++ need not repeat the GLSL.
// Only what DESIGN.md's "Shaders that serve both backends" allows is accepted.
#pragma once

#include <array>
#include <cstdint>
#include <span>
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

}  // namespace volgraph::rhi
