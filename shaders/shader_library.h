// The SPIR-V of the shaders in shaders/, compiled at build time.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace volgraph {

// Empty when there is no shader of that name.
std::span<const uint32_t> shader_spirv(std::string_view name);

// The name of every shader in shaders/ (the folder is the list), sorted.
std::span<const std::string_view> shader_spirv_names();

}  // namespace volgraph
