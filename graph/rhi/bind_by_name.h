// Bind groups filled by shader variable name (ShaderBinding, generated from the SPIR-V)
// rather than by binding number, so that two same-typed resources cannot swap silently:
//   c.bind_group(program_, {bind(shader::transmittance, c.view(t_.transmittance)), …})
// The set is the one the entries name; check_bound_set throws when they do not fill
// exactly one set's layout.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "graph/rhi/rhi.h"
#include "graph/rhi/shader_binding.h"

namespace volgraph::rhi {

// One entry of a bind group and the shader variable it fills.
struct BoundResource {
  ShaderBinding variable;
  BindGroupEntry entry;
};

inline BoundResource bind(ShaderBinding variable, BufferId buffer) { return {variable, BindGroupEntry::of(variable.binding, buffer)}; }
inline BoundResource bind(ShaderBinding variable, TextureViewId view) { return {variable, BindGroupEntry::of(variable.binding, view)}; }
inline BoundResource bind(ShaderBinding variable, SamplerId sampler) { return {variable, BindGroupEntry::of(variable.binding, sampler)}; }

// The set every resource names, checked against `layouts` (set i at index i): all name one
// set, no binding twice, and they cover exactly that layout's bindings. Throws
// std::logic_error naming the pass, its shader and the variable otherwise.
uint32_t check_bound_set(std::span<const BoundResource> resources, std::span<const BindGroupLayoutDesc> layouts,
                         std::string_view pass, std::string_view shader);

// The resources' entries, in their order.
std::vector<BindGroupEntry> entries_of(std::span<const BoundResource> resources);

}  // namespace volgraph::rhi
