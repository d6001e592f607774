// See twin_shader.h.
#include "tests/gpu/twin_shader.h"

#include "graph/access.h"
#include "graph/rhi/spirv_reflect.h"
#include "tests/gpu/shaders/gpu_test_shaders.h"

namespace volgraph::testing {

std::vector<std::byte> run_twin_shader(rhi::Device& device, const char* shader, const std::vector<TwinInput>& inputs,
                                       size_t rows, uint64_t result_bytes) {
  using namespace rhi;
  std::vector<BindGroupEntry> entries;
  for (const TwinInput& in : inputs) {
    const BufferId buffer = device.create_buffer({"twin input", in.bytes.size(), in.usage | buffer_usage::copy_dst});
    device.write_buffer(buffer, 0, in.bytes);
    entries.push_back(BindGroupEntry::of(uint32_t(entries.size()), buffer));
  }
  const BufferId output = device.create_buffer({"results", result_bytes, buffer_usage::storage | buffer_usage::copy_src});
  const BufferId readback = device.create_buffer({"readback", result_bytes, buffer_usage::copy_dst});
  entries.push_back(BindGroupEntry::of(uint32_t(entries.size()), output));

  const auto spirv = gpu_test_shader_spirv(shader);
  const rhi::ShaderStageCode stage{spirv, shader_stage::compute};
  const auto layouts = reflect_bind_group_layouts({&stage, 1}, shader);
  const BindGroupLayoutId layout = device.create_bind_group_layout(layouts[0]);
  const ComputePipelineId pipeline = device.create_compute_pipeline({shader, device.create_shader_module(shader, spirv), "main", {layout}});
  const BindGroupId group = device.create_bind_group({shader, layout, entries});

  auto encoder = device.create_command_encoder(shader);
  const AccessState written = access_state(Usage::storage_write, PassKind::compute, ResourceKind::buffer);
  const AccessState copied = access_state(Usage::copy_src, PassKind::transfer, ResourceKind::buffer);
  const ResourceBarrier before{{}, output, {}, written}, after{{}, output, written, copied};
  encoder->barrier({&before, 1});
  encoder->begin_compute_pass(shader);
  encoder->set_pipeline(pipeline);
  encoder->set_bind_group(0, group);
  encoder->dispatch(uint32_t((rows + 63) / 64));
  encoder->end_compute_pass();
  encoder->barrier({&after, 1});
  encoder->copy_buffer_to_buffer(output, readback, result_bytes);
  device.submit(std::move(encoder));
  return device.read_buffer(readback);
}

}  // namespace volgraph::testing
