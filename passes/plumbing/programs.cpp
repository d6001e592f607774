#include "passes/plumbing/programs.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "graph/rhi/device_error.h"
#include "graph/rhi/spirv_reflect.h"
#include "shaders/shader_library.h"

namespace volgraph::plumbing {
namespace {

// The device's replacement of the shader (view's hot reload), else the embedded one.
std::span<const uint32_t> spirv_of(const rhi::Device& device, const std::string& shader) {
  if (const std::span<const uint32_t> replaced = device.replaced_shader(shader); !replaced.empty()) return replaced;
  const std::span<const uint32_t> words = shader_spirv(shader);
  if (words.empty()) throw DeviceError(DeviceError::Kind::other, "no shader named " + shader + " in shaders/");
  return words;
}

std::vector<rhi::BindGroupLayoutId> create_layouts(rhi::Device& device, const std::vector<rhi::BindGroupLayoutDesc>& descs) {
  std::vector<rhi::BindGroupLayoutId> layouts;
  for (const rhi::BindGroupLayoutDesc& d : descs) layouts.push_back(device.cached_bind_group_layout(d));
  return layouts;
}

}  // namespace

std::array<uint32_t, 3> ComputeProgram::groups_for(Extent size) const {
  const uint32_t extent[3] = {size.width, size.height, std::max(1u, size.depth)};
  std::array<uint32_t, 3> groups{};
  for (size_t i = 0; i < 3; ++i) groups[i] = (extent[i] + workgroup_size[i] - 1) / workgroup_size[i];
  return groups;
}

ComputeProgram create_compute_program(rhi::Device& device, const std::string& shader) {
  const std::span<const uint32_t> spirv = spirv_of(device, shader);
  const rhi::ShaderStageCode stage{spirv, rhi::shader_stage::compute};
  ComputeProgram program;
  program.layout_descs = rhi::reflect_bind_group_layouts({&stage, 1}, shader);
  program.layouts = create_layouts(device, program.layout_descs);
  program.shader = shader;
  program.workgroup_size = rhi::reflect_workgroup_size(spirv);
  program.uniform_blocks = rhi::reflect_uniform_blocks({&stage, 1}, shader);
  program.pipeline = device.cached_compute_pipeline({shader, device.cached_shader_module(shader, spirv), "main", program.layouts});
  return program;
}

namespace {

// The first binding of `shader` that a layout made for `layout` does not serve (absent, of
// another kind, not visible to all its stages, or unfilterable where the shader filters),
// −1 when it serves them all (a layout may hold bindings a pipeline's shaders do not use,
// and a filterable texture serves one the shader only loads from).
int unserved_binding(const rhi::BindGroupLayoutDesc& layout, const rhi::BindGroupLayoutDesc& shader) {
  for (const rhi::LayoutEntry& x : shader.entries) {
    const auto y = std::find_if(layout.entries.begin(), layout.entries.end(), [&](const rhi::LayoutEntry& e) { return e.binding == x.binding; });
    if (y == layout.entries.end() || (x.visibility & ~y->visibility) != 0 || x.type != y->type || x.texture_kind != y->texture_kind ||
        x.storage_format != y->storage_format || (x.filtered && !y->filtered) || x.storage_access != y->storage_access) {
      return int(x.binding);
    }
  }
  return -1;
}

RenderProgram render_program(rhi::Device& device, rhi::RenderPipelineDesc desc, const std::string& vertex, const std::string& fragment,
                             const RenderProgram* layouts_of) {
  std::vector<rhi::ShaderStageCode> stages = {{spirv_of(device, vertex), rhi::shader_stage::vertex}};
  if (!fragment.empty()) stages.push_back({spirv_of(device, fragment), rhi::shader_stage::fragment});
  RenderProgram program;
  program.shader = fragment.empty() ? vertex : vertex + " + " + fragment;
  program.layout_descs = rhi::reflect_bind_group_layouts(stages, desc.label);
  if (layouts_of) {
    if (program.layout_descs.size() > layouts_of->layout_descs.size()) {
      throw std::logic_error(desc.label + ": its shaders declare more sets than the layouts it shares hold");
    }
    for (size_t set = 0; set < program.layout_descs.size(); ++set) {
      const int binding = unserved_binding(layouts_of->layout_descs[set], program.layout_descs[set]);
      if (binding < 0) continue;
      throw std::logic_error(desc.label + ": set " + std::to_string(set) + " binding " + std::to_string(binding) +
                             " is not in the layouts it shares, or not of the same kind and stages");
    }
    program.layouts = layouts_of->layouts;
    program.layout_descs = layouts_of->layout_descs;
  } else {
    program.layouts = create_layouts(device, program.layout_descs);
  }
  program.uniform_blocks = rhi::reflect_uniform_blocks(stages, desc.label);
  desc.vertex_module = device.cached_shader_module(vertex, stages[0].spirv);
  if (!fragment.empty()) desc.fragment_module = device.cached_shader_module(fragment, stages[1].spirv);
  desc.layouts = program.layouts;
  program.pipeline = device.cached_render_pipeline(desc);
  return program;
}

}  // namespace

RenderProgram create_render_program(rhi::Device& device, rhi::RenderPipelineDesc desc, const std::string& vertex,
                                    const std::string& fragment) {
  return render_program(device, std::move(desc), vertex, fragment, nullptr);
}

RenderProgram create_render_program(rhi::Device& device, rhi::RenderPipelineDesc desc, const std::string& vertex,
                                    const std::string& fragment, const RenderProgram& layouts_of) {
  return render_program(device, std::move(desc), vertex, fragment, &layouts_of);
}

void dispatch(rhi::CommandEncoder& encoder, const std::string& label, const ComputeProgram& program,
              std::initializer_list<rhi::BindGroupId> groups, Extent invocations) {
  encoder.begin_compute_pass(label);
  encoder.set_pipeline(program.pipeline);
  uint32_t set = 0;
  for (const rhi::BindGroupId group : groups) {
    if (group) encoder.set_bind_group(set, group);
    ++set;
  }
  const auto counts = program.groups_for(invocations);
  encoder.dispatch(counts[0], counts[1], counts[2]);
  encoder.end_compute_pass();
}

rhi::BufferId create_uniform_buffer(rhi::Device& device, const std::string& label, std::span<const std::byte> bytes) {
  const rhi::BufferId buffer = device.create_buffer({label, bytes.size(), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  device.write_buffer(buffer, 0, bytes);
  return buffer;
}

const rhi::UniformBlockLayout& uniform_block_at(const std::vector<rhi::UniformBlockLayout>& blocks, uint32_t set, uint32_t binding) {
  for (const rhi::UniformBlockLayout& b : blocks) {
    if (b.set == set && b.binding == binding) return b;
  }
  throw std::logic_error("the shader has no uniform block at set " + std::to_string(set) + ", binding " + std::to_string(binding));
}

}  // namespace volgraph::plumbing
