#include "graph/access.h"

#include <array>

namespace volgraph {
namespace {

struct UsageInfo {
  std::string_view name;
  bool reads;
  bool writes;
};

constexpr std::array<UsageInfo, 11> kUsages = {{
    {"sampled", true, false},
    {"storage_read", true, false},
    {"storage_write", false, true},
    {"storage_read_write", true, true},
    {"uniform_read", true, false},
    {"color_attachment", false, true},
    {"color_attachment_load", true, true},
    {"depth_attachment", true, true},
    {"depth_read", true, false},
    {"copy_src", true, false},
    {"copy_dst", false, true},
}};

constexpr std::array<std::string_view, 9> kLayouts = {
    "undefined", "general", "shader_read_only", "color_attachment", "depth_attachment",
    "depth_read_only", "transfer_src", "transfer_dst", "none"};

constexpr std::array<std::string_view, 8> kStages = {
    "vertex_shader", "fragment_shader", "early_fragment_tests", "late_fragment_tests",
    "color_attachment_output", "compute_shader", "copy", "all_commands"};

constexpr std::array<std::string_view, 12> kAccesses = {
    "shader_sampled_read", "shader_storage_read", "shader_storage_write", "uniform_read",
    "color_attachment_read", "color_attachment_write", "depth_stencil_read", "depth_stencil_write",
    "transfer_read", "transfer_write", "memory_read", "memory_write"};

template <size_t N>
std::string bit_names(uint32_t bits, const std::array<std::string_view, N>& names) {
  if (bits == 0) return "none";
  std::string out;
  for (size_t i = 0; i < N; ++i) {
    if (!(bits & (1u << i))) continue;
    if (!out.empty()) out += '|';
    out += names[i];
  }
  return out;
}

uint32_t shader_stage(PassKind kind) {
  return kind == PassKind::compute ? stage::compute_shader : stage::fragment_shader;
}

}  // namespace

std::string_view usage_name(Usage usage) { return kUsages[static_cast<size_t>(usage)].name; }

bool usage_from_name(std::string_view name, Usage* out) {
  for (size_t i = 0; i < kUsages.size(); ++i) {
    if (kUsages[i].name != name) continue;
    *out = static_cast<Usage>(i);
    return true;
  }
  return false;
}

bool usage_reads(Usage usage) { return kUsages[static_cast<size_t>(usage)].reads; }
bool usage_writes(Usage usage) { return kUsages[static_cast<size_t>(usage)].writes; }

bool usage_fits_kind(Usage usage, ResourceKind kind) {
  switch (usage) {
    case Usage::sampled:
      return kind != ResourceKind::buffer;
    case Usage::uniform_read:
      return kind == ResourceKind::buffer;
    case Usage::color_attachment:
    case Usage::color_attachment_load:
    case Usage::depth_attachment:
    case Usage::depth_read:
      return kind == ResourceKind::texture2d || kind == ResourceKind::texture_cube;  // a cube: a face at a time (PassSetup::face_view)
    default:
      return true;
  }
}

std::string_view layout_name(Layout layout) { return kLayouts[static_cast<size_t>(layout)]; }
std::string stage_names(uint32_t stages) { return bit_names(stages, kStages); }
std::string access_names(uint32_t accesses) { return bit_names(accesses, kAccesses); }

AccessState access_state(Usage usage, PassKind pass_kind, ResourceKind resource_kind) {
  const bool buffer = resource_kind == ResourceKind::buffer;
  const uint32_t shader = shader_stage(pass_kind);
  const uint32_t depth_tests = stage::early_fragment_tests | stage::late_fragment_tests;
  AccessState s;
  switch (usage) {
    case Usage::sampled:  // a graphics pass may sample in its vertex shader too (light_volume's faces)
      s = {pass_kind == PassKind::graphics ? stage::vertex_shader | shader : shader, access::shader_sampled_read, Layout::shader_read_only};
      break;
    case Usage::storage_read:
      s = {shader, access::shader_storage_read, Layout::general};
      break;
    case Usage::storage_write:
      s = {shader, access::shader_storage_write, Layout::general};
      break;
    case Usage::storage_read_write:
      s = {shader, access::shader_storage_read | access::shader_storage_write, Layout::general};
      break;
    case Usage::uniform_read:
      s = {shader | (pass_kind == PassKind::graphics ? stage::vertex_shader : 0), access::uniform_read,
           Layout::none};
      break;
    case Usage::color_attachment:
      s = {stage::color_attachment_output, access::color_attachment_write, Layout::color_attachment};
      break;
    case Usage::color_attachment_load:
      s = {stage::color_attachment_output, access::color_attachment_read | access::color_attachment_write,
           Layout::color_attachment};
      break;
    case Usage::depth_attachment:
      s = {depth_tests, access::depth_stencil_read | access::depth_stencil_write, Layout::depth_attachment};
      break;
    case Usage::depth_read:
      s = {depth_tests, access::depth_stencil_read, Layout::depth_read_only};
      break;
    case Usage::copy_src:
      s = {stage::copy, access::transfer_read, Layout::transfer_src};
      break;
    case Usage::copy_dst:
      s = {stage::copy, access::transfer_write, Layout::transfer_dst};
      break;
  }
  if (buffer) s.layout = Layout::none;
  return s;
}

}  // namespace volgraph
