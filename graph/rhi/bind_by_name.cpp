#include "graph/rhi/bind_by_name.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

namespace volgraph::rhi {
namespace {

std::string describe(const ShaderBinding& v) {
  return "'" + std::string(v.name) + "' (set " + std::to_string(v.set) + ", binding " + std::to_string(v.binding) + ")";
}

struct BindSite {
  std::string_view pass;
  std::string_view shader;
};

[[noreturn]] void fail(const BindSite& what, const std::string& message) {
  throw std::logic_error("pass " + std::string(what.pass) + ": a bind group for " + std::string(what.shader) + " " + message);
}

bool layout_has(const BindGroupLayoutDesc& layout, uint32_t binding) {
  return std::ranges::any_of(layout.entries, [&](const LayoutEntry& e) { return e.binding == binding; });
}

std::string names_of(std::span<const BoundResource> resources) {
  std::string names;
  for (const BoundResource& r : resources) names += (names.empty() ? "" : ", ") + std::string(r.variable.name);
  return names;
}

}  // namespace

uint32_t check_bound_set(std::span<const BoundResource> resources, std::span<const BindGroupLayoutDesc> layouts,
                         std::string_view pass, std::string_view shader) {
  const BindSite what{pass, shader};
  if (resources.empty()) fail(what, "has no entries");
  const ShaderBinding& first = resources.front().variable;
  if (first.set >= layouts.size()) fail(what, "entry " + describe(first) + " names a set the shader does not declare");
  const BindGroupLayoutDesc& layout = layouts[first.set];
  std::set<uint32_t> bound;
  for (const BoundResource& r : resources) {
    // One bind group fills one set: an entry of another set would land at the wrong binding.
    if (r.variable.set != first.set) fail(what, "mixes sets: " + describe(first) + " and " + describe(r.variable));
    if (!layout_has(layout, r.variable.binding)) fail(what, "entry " + describe(r.variable) + " is not in the shader's layout");
    if (!bound.insert(r.variable.binding).second) fail(what, "binds " + describe(r.variable) + " twice");
  }
  for (const LayoutEntry& e : layout.entries) {
    if (!bound.contains(e.binding)) {
      fail(what, "of set " + std::to_string(first.set) + " leaves binding " + std::to_string(e.binding) +
                     " unbound (it binds " + names_of(resources) + ")");
    }
  }
  return first.set;
}

std::vector<BindGroupEntry> entries_of(std::span<const BoundResource> resources) {
  std::vector<BindGroupEntry> entries;
  entries.reserve(resources.size());
  for (const BoundResource& r : resources) entries.push_back(r.entry);
  return entries;
}

}  // namespace volgraph::rhi
