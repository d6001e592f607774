// Runs a test compute shader (tests/gpu/shaders) over a table of inputs and reads its
// results back: how the GPU twin tests hold a shared GLSL include to its CPU twin.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "graph/rhi/rhi.h"

namespace volgraph::testing {

// A buffer bound to a test shader, in binding order.
struct TwinInput {
  std::span<const std::byte> bytes;
  uint32_t usage;  // buffer_usage::uniform or storage
};

// Runs test shader `shader` over `rows` rows (64 invocations a workgroup) with `inputs`
// at bindings 0 … n − 1 and a storage buffer of `result_bytes` after them; returns it.
std::vector<std::byte> run_twin_shader(rhi::Device& device, const char* shader, const std::vector<TwinInput>& inputs,
                                       size_t rows, uint64_t result_bytes);

}  // namespace volgraph::testing
