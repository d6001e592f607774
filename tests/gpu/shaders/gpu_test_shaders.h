// The SPIR-V of the test-only shaders in tests/gpu/shaders/, compiled at build time.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace volgraph {

// Empty when there is no test shader of that name.
std::span<const uint32_t> gpu_test_shader_spirv(std::string_view name);

}  // namespace volgraph
