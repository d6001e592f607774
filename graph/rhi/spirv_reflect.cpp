// SPIR-V reflection (spirv_reflect.h): one walk over a module's word stream collects its
// decorations, types and variables; each resource variable becomes a LayoutEntry, and
// the stages' entries are merged per set and binding. Numbers are from the SPIR-V 1.3
// specification (what glslang emits for Vulkan 1.1); § names the section.
#include "graph/rhi/spirv_reflect.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace volgraph::rhi {
namespace {

constexpr uint32_t kMagicNumber = 0x07230203;  // §3.1 Magic Number
constexpr size_t kHeaderWords = 5;             // §2.3 Physical Layout of a SPIR-V Module and Instruction
constexpr uint32_t kMaxSets = 4;               // DESIGN.md: at most 4 descriptor sets (WebGPU)

namespace op {                               // §3.32 Instructions
constexpr uint32_t entry_point = 15;         // §3.32.5 Mode-Setting Instructions
constexpr uint32_t execution_mode = 16;      // §3.32.5
constexpr uint32_t type_image = 25;          // §3.32.6 Type-Declaration Instructions
constexpr uint32_t type_sampler = 26;        // §3.32.6
constexpr uint32_t type_sampled_image = 27;  // §3.32.6
constexpr uint32_t type_array = 28;          // §3.32.6
constexpr uint32_t type_runtime_array = 29;  // §3.32.6
constexpr uint32_t type_struct = 30;         // §3.32.6
constexpr uint32_t type_pointer = 32;        // §3.32.6
constexpr uint32_t function = 54;            // §3.32.9 Function Instructions
constexpr uint32_t function_parameter = 55;  // §3.32.9
constexpr uint32_t function_call = 57;       // §3.32.9
constexpr uint32_t variable = 59;            // §3.32.8 Memory Instructions
constexpr uint32_t load = 61;                // §3.32.8
constexpr uint32_t sampled_image = 86;       // §3.32.10 Image Instructions
constexpr uint32_t image_sample_first = 87;  // §3.32.10: OpImageSampleImplicitLod …
constexpr uint32_t image_sample_last = 94;   // … OpImageSampleProjDrefExplicitLod
constexpr uint32_t image_gather = 96;        // §3.32.10
constexpr uint32_t image_dref_gather = 97;   // §3.32.10
constexpr uint32_t image_query_lod = 105;    // §3.32.10
constexpr uint32_t decorate = 71;            // §3.32.3 Annotation Instructions
constexpr uint32_t member_decorate = 72;     // §3.32.3
}  // namespace op

namespace decoration {  // §3.20 Decoration
constexpr uint32_t block = 2;
constexpr uint32_t buffer_block = 3;
constexpr uint32_t non_writable = 24;
constexpr uint32_t non_readable = 25;
constexpr uint32_t binding = 33;
constexpr uint32_t descriptor_set = 34;
}  // namespace decoration

namespace storage_class {  // §3.7 Storage Class
constexpr uint32_t uniform_constant = 0;
constexpr uint32_t uniform = 2;
constexpr uint32_t push_constant = 9;
constexpr uint32_t storage_buffer = 12;
}  // namespace storage_class

namespace execution_model {  // §3.3 Execution Model
constexpr uint32_t vertex = 0;
constexpr uint32_t fragment = 4;
constexpr uint32_t gl_compute = 5;
}  // namespace execution_model

constexpr uint32_t kExecutionModeLocalSize = 17;  // §3.6 Execution Mode

namespace dim {  // §3.8 Dim
constexpr uint32_t two_d = 1;
constexpr uint32_t three_d = 2;
constexpr uint32_t cube = 3;
}  // namespace dim

namespace image_sampled {  // §3.32.6 OpTypeImage, the Sampled operand
constexpr uint32_t with_sampler = 1;
constexpr uint32_t storage = 2;
}  // namespace image_sampled

// §3.11 Image Format: the SPIR-V formats volgraph has a Format for.
constexpr std::pair<uint32_t, Format> kImageFormats[] = {
    {1, Format::rgba32_float},     // Rgba32f
    {2, Format::rgba16_float},     // Rgba16f
    {3, Format::r32_float},        // R32f
    {4, Format::rgba8_unorm},      // Rgba8
    {6, Format::rg32_float},       // Rg32f
    {7, Format::rg16_float},       // Rg16f
    {8, Format::r11g11b10_float},  // R11fG11fB10f
    {9, Format::r16_float},        // R16f
    {15, Format::r8_unorm},        // R8
    {33, Format::r32_uint},        // R32ui
};

// One instruction: its opcode and the words after the first.
struct Instruction {
  uint32_t opcode = 0;
  std::span<const uint32_t> operands;
};

uint32_t operand(const Instruction& instruction, size_t index) {
  if (index >= instruction.operands.size()) {
    throw std::runtime_error("SPIR-V: opcode " + std::to_string(instruction.opcode) + " has too few operands");
  }
  return instruction.operands[index];
}

// §2.3: five header words, then instructions whose first word holds the word count
// (high 16 bits) and the opcode (low 16 bits).
std::vector<Instruction> parse_instructions(std::span<const uint32_t> spirv) {
  if (spirv.size() < kHeaderWords || spirv[0] != kMagicNumber) {
    throw std::runtime_error("SPIR-V: not a SPIR-V module (no header or magic number)");
  }
  std::vector<Instruction> instructions;
  for (size_t at = kHeaderWords; at < spirv.size();) {
    const uint32_t word_count = spirv[at] >> 16;
    if (word_count == 0 || at + word_count > spirv.size()) {
      throw std::runtime_error("SPIR-V: malformed instruction at word " + std::to_string(at));
    }
    instructions.push_back({spirv[at] & 0xffffu, spirv.subspan(at + 1, word_count - 1)});
    at += word_count;
  }
  return instructions;
}

struct Decorations {
  std::optional<uint32_t> set;
  std::optional<uint32_t> binding;
  bool block = false;
  bool buffer_block = false;
  bool non_writable = false;
  bool non_readable = false;
};

// What reflection needs of one module.
struct Module {
  std::vector<uint32_t> execution_models;                                 // of its entry points
  std::unordered_map<uint32_t, Decorations> decorations;                  // by target id
  std::unordered_map<uint32_t, std::set<uint32_t>> non_writable_members;  // struct id → member indices
  std::unordered_map<uint32_t, Instruction> types;                        // result id → declaration
  std::vector<Instruction> variables;
  // Texture and sampler variables some instruction samples through (filters with).
  std::unordered_map<uint32_t, uint32_t> loaded_from;                          // OpLoad result → variable
  std::unordered_map<uint32_t, std::pair<uint32_t, uint32_t>> sampled_images;  // result → image, sampler loads
  std::set<uint32_t> sampled_through;                                          // OpSampledImage results sampled
  std::set<uint32_t> filtered_variables;
  // Textures and samplers handed to functions (by pointer): each parameter's function and
  // position, and every call's arguments, to follow a parameter back to its variables.
  uint32_t current_function = 0;
  std::unordered_map<uint32_t, std::pair<uint32_t, size_t>> parameters;      // parameter → function, index
  std::unordered_map<uint32_t, size_t> parameter_counts;                     // function → parameters so far
  std::unordered_map<uint32_t, std::vector<std::vector<uint32_t>>> calls;    // function → each call's arguments
};

bool is_type_declaration(uint32_t opcode) {
  switch (opcode) {
    case op::type_image:
    case op::type_sampler:
    case op::type_sampled_image:
    case op::type_array:
    case op::type_runtime_array:
    case op::type_struct:
    case op::type_pointer: return true;
    default: return false;
  }
}

// OpDecorate: Target, Decoration, then the decoration's literals.
void record_decoration(Module& module, const Instruction& decorate) {
  Decorations& target = module.decorations[operand(decorate, 0)];
  switch (operand(decorate, 1)) {
    case decoration::descriptor_set: target.set = operand(decorate, 2); return;
    case decoration::binding: target.binding = operand(decorate, 2); return;
    case decoration::block: target.block = true; return;
    case decoration::buffer_block: target.buffer_block = true; return;
    case decoration::non_writable: target.non_writable = true; return;
    case decoration::non_readable: target.non_readable = true; return;
    default: return;
  }
}

// OpMemberDecorate: Structure Type, Member, Decoration, ...
void record_member_decoration(Module& module, const Instruction& decorate) {
  if (operand(decorate, 2) != decoration::non_writable) return;
  module.non_writable_members[operand(decorate, 0)].insert(operand(decorate, 1));
}

// Instructions that sample through an OpSampledImage (its operand 2): they filter.
bool samples_with_filter(uint32_t opcode) {
  const bool sample = opcode >= op::image_sample_first && opcode <= op::image_sample_last;
  return sample || opcode == op::image_gather || opcode == op::image_dref_gather || opcode == op::image_query_lod;
}

void record(Module& module, const Instruction& instruction) {
  if (is_type_declaration(instruction.opcode)) {
    module.types.emplace(operand(instruction, 0), instruction);
    return;
  }
  if (samples_with_filter(instruction.opcode)) {
    module.sampled_through.insert(operand(instruction, 2));
    return;
  }
  switch (instruction.opcode) {
    case op::entry_point: module.execution_models.push_back(operand(instruction, 0)); return;
    case op::decorate: record_decoration(module, instruction); return;
    case op::member_decorate: record_member_decoration(module, instruction); return;
    case op::variable: module.variables.push_back(instruction); return;
    case op::load: module.loaded_from[operand(instruction, 1)] = operand(instruction, 2); return;  // Result, Pointer
    case op::function: module.current_function = operand(instruction, 1); return;  // Result Type, Result, …
    case op::function_parameter:  // Result Type, Result
      module.parameters[operand(instruction, 1)] = {module.current_function, module.parameter_counts[module.current_function]++};
      return;
    case op::function_call:  // Result Type, Result, Function, Arguments…
      module.calls[operand(instruction, 2)].emplace_back(instruction.operands.begin() + 3, instruction.operands.end());
      return;
    case op::sampled_image:  // Result Type, Result, Image, Sampler
      module.sampled_images[operand(instruction, 1)] = {operand(instruction, 2), operand(instruction, 3)};
      return;
    default: return;
  }
}

// The variables a pointer may be: itself, or — a function's parameter — whatever every
// call passes there, followed through nested calls.
void add_variables_behind(Module& module, uint32_t pointer, std::set<uint32_t>& visited) {
  if (!visited.insert(pointer).second) return;
  const auto parameter = module.parameters.find(pointer);
  if (parameter == module.parameters.end()) {
    module.filtered_variables.insert(pointer);
    return;
  }
  const auto [function, index] = parameter->second;
  for (const std::vector<uint32_t>& arguments : module.calls[function]) {
    if (index < arguments.size()) add_variables_behind(module, arguments[index], visited);
  }
}

// The texture and sampler variables behind every sampled image some instruction samples.
void find_filtered_variables(Module& module) {
  std::set<uint32_t> visited;
  auto add_loaded = [&](uint32_t loaded) {
    const auto found = module.loaded_from.find(loaded);
    if (found != module.loaded_from.end()) add_variables_behind(module, found->second, visited);
  };
  for (const uint32_t sampled : module.sampled_through) {
    const auto found = module.sampled_images.find(sampled);
    if (found == module.sampled_images.end()) continue;
    add_loaded(found->second.first);
    add_loaded(found->second.second);
  }
}

Module read_module(std::span<const uint32_t> spirv) {
  Module module;
  for (const Instruction& instruction : parse_instructions(spirv)) record(module, instruction);
  find_filtered_variables(module);
  return module;
}

Decorations decorations_of(const Module& module, uint32_t id) {
  const auto found = module.decorations.find(id);
  return found == module.decorations.end() ? Decorations{} : found->second;
}

constexpr std::pair<uint32_t, std::string_view> kStageNames[] = {
    {shader_stage::vertex, "vertex"}, {shader_stage::fragment, "fragment"}, {shader_stage::compute, "compute"}};

// "vertex", "vertex+fragment".
std::string stage_names(uint32_t stages) {
  std::string names;
  for (const auto& [bit, name] : kStageNames) {
    if ((stages & bit) == 0) continue;
    if (!names.empty()) names += "+";
    names += name;
  }
  return names.empty() ? "unknown" : names;
}

std::string_view binding_type_name(BindingType type) {
  switch (type) {
    case BindingType::uniform_buffer: return "uniform buffer";
    case BindingType::storage_buffer: return "storage buffer";
    case BindingType::read_only_storage_buffer: return "read-only storage buffer";
    case BindingType::sampled_texture: return "sampled texture";
    case BindingType::sampler: return "sampler";
    case BindingType::storage_texture: return "storage texture";
  }
  return "?";
}

// "sampled texture texture2d", "storage texture texture3d rgba16_float", "sampler".
std::string describe(const LayoutEntry& entry) {
  std::string text(binding_type_name(entry.type));
  const bool is_texture = entry.type == BindingType::sampled_texture || entry.type == BindingType::storage_texture;
  if (is_texture) text += " " + std::string(kind_name(entry.texture_kind));
  if (entry.type == BindingType::storage_texture) text += " " + std::string(format_info(entry.storage_format).name);
  return text;
}

[[noreturn]] void fail(std::string_view label, uint32_t stage, const std::string& reason) {
  throw std::runtime_error(std::string(label) + ": " + stage_names(stage) + " shader: " + reason);
}

// The binding being reflected, for error messages.
struct Where {
  std::string_view label;
  uint32_t stage = 0;
  uint32_t set = 0;
  uint32_t binding = 0;

  [[noreturn]] void fail(const std::string& reason) const {
    rhi::fail(label, stage, "set " + std::to_string(set) + ", binding " + std::to_string(binding) + ": " + reason);
  }
};

const Instruction& type_of(const Module& module, uint32_t id, const Where& where) {
  const auto found = module.types.find(id);
  if (found == module.types.end()) where.fail("type %" + std::to_string(id) + " is not a resource type");
  return found->second;
}

// OpTypePointer: Result, Storage Class, Type.
const Instruction& pointee_of(const Module& module, uint32_t pointer_id, const Where& where) {
  const Instruction& pointer = type_of(module, pointer_id, where);
  if (pointer.opcode != op::type_pointer) where.fail("variable type is not a pointer");
  return type_of(module, operand(pointer, 2), where);
}

ResourceKind image_kind(uint32_t image_dim, const Where& where) {
  if (image_dim == dim::two_d) return ResourceKind::texture2d;
  if (image_dim == dim::three_d) return ResourceKind::texture3d;
  if (image_dim == dim::cube) where.fail("cube textures have no ResourceKind");
  where.fail("image Dim " + std::to_string(image_dim) + " is neither 2D nor 3D");
}

Format storage_format(uint32_t image_format, const Where& where) {
  const auto* known = std::ranges::find(kImageFormats, image_format, &std::pair<uint32_t, Format>::first);
  const bool mapped = known != std::end(kImageFormats);
  if (mapped && format_info(known->second).storage_capable) return known->second;
  where.fail("storage image format " + std::to_string(image_format) +
             " (SPIR-V Image Format) is not a storage format of both backends");
}

// OpTypeImage: Result, Sampled Type, Dim, Depth, Arrayed, MS, Sampled, Image Format.
LayoutEntry image_entry(const Instruction& image, const Where& where) {
  if (operand(image, 4) != 0) where.fail("arrayed images are not supported");
  if (operand(image, 5) != 0) where.fail("multisampled images are not supported");
  const ResourceKind kind = image_kind(operand(image, 2), where);
  const uint32_t sampled = operand(image, 6);
  if (sampled == image_sampled::with_sampler) return {.type = BindingType::sampled_texture, .texture_kind = kind};
  if (sampled != image_sampled::storage) where.fail("image is neither sampled nor storage (Sampled 0)");
  return {.type = BindingType::storage_texture,
          .texture_kind = kind,
          .storage_format = storage_format(operand(image, 7), where)};
}

// OpTypeStruct: Result, then one type per member.
bool all_members_non_writable(const Module& module, const Instruction& block) {
  const size_t member_count = block.operands.size() - 1;
  const auto found = module.non_writable_members.find(operand(block, 0));
  return member_count > 0 && found != module.non_writable_members.end() && found->second.size() == member_count;
}

// Uniform + Block: a uniform buffer. StorageBuffer + Block, or Uniform + BufferBlock
// (SPIR-V before 1.3, §3.20): a storage buffer, read-only when it or all members are NonWritable.
LayoutEntry buffer_entry(const Module& module, const Instruction& block, uint32_t storage, bool non_writable,
                         const Where& where) {
  const Decorations decorations = decorations_of(module, operand(block, 0));
  const bool is_storage = storage == storage_class::storage_buffer || decorations.buffer_block;
  if (!is_storage && !decorations.block) where.fail("uniform struct without the Block decoration");
  if (!is_storage) return {.type = BindingType::uniform_buffer};
  const bool read_only = non_writable || all_members_non_writable(module, block);
  return {.type = read_only ? BindingType::read_only_storage_buffer : BindingType::storage_buffer};
}

LayoutEntry resource_entry(const Module& module, const Instruction& type, uint32_t storage, bool non_writable,
                           const Where& where) {
  switch (type.opcode) {
    case op::type_sampler: return {.type = BindingType::sampler};
    case op::type_image: return image_entry(type, where);
    case op::type_struct: return buffer_entry(module, type, storage, non_writable, where);
    case op::type_sampled_image:
      where.fail("combined image samplers are not supported: declare a texture and a sampler");
    case op::type_array:
    case op::type_runtime_array: where.fail("arrays of resources are not supported: one resource per binding");
    default: where.fail("unsupported resource type (opcode " + std::to_string(type.opcode) + ")");
  }
}

bool is_resource_storage(uint32_t storage) {
  return storage == storage_class::uniform_constant || storage == storage_class::uniform ||
         storage == storage_class::storage_buffer;
}

// A resource variable's set and its entry (visible to `stage`).
struct DeclaredBinding {
  uint32_t set = 0;
  LayoutEntry entry;
};

// OpVariable: Result Type, Result, Storage Class. Not a resource: nullopt.
std::optional<DeclaredBinding> reflect_variable(const Module& module, const Instruction& variable, uint32_t stage,
                                                std::string_view label) {
  const uint32_t storage = operand(variable, 2);
  if (storage == storage_class::push_constant)
    fail(label, stage, "push constants are not supported: use a uniform buffer");
  if (!is_resource_storage(storage)) return std::nullopt;
  const Decorations decorations = decorations_of(module, operand(variable, 1));
  if (!decorations.set || !decorations.binding) fail(label, stage, "a resource without DescriptorSet and Binding");
  const Where where{label, stage, *decorations.set, *decorations.binding};
  if (where.set >= kMaxSets) where.fail("at most " + std::to_string(kMaxSets) + " sets (0 to 3)");
  const Instruction& type = pointee_of(module, operand(variable, 0), where);
  LayoutEntry entry = resource_entry(module, type, storage, decorations.non_writable, where);
  entry.binding = where.binding;
  entry.visibility = stage;
  entry.filtered = module.filtered_variables.contains(operand(variable, 1));
  if (decorations.non_writable) entry.storage_access = StorageAccess::read_only;
  if (decorations.non_readable) entry.storage_access = StorageAccess::write_only;
  return DeclaredBinding{where.set, entry};
}

uint32_t execution_model_of(uint32_t stage, std::string_view label) {
  switch (stage) {
    case shader_stage::vertex: return execution_model::vertex;
    case shader_stage::fragment: return execution_model::fragment;
    case shader_stage::compute: return execution_model::gl_compute;
    default: fail(label, stage, "stage bits " + std::to_string(stage) + " are not one shader_stage bit");
  }
}

void check_entry_point(const Module& module, uint32_t stage, std::string_view label) {
  if (std::ranges::count(module.execution_models, execution_model_of(stage, label)) > 0) return;
  fail(label, stage, "the module has no entry point of that stage");
}

bool same_resource(const LayoutEntry& a, const LayoutEntry& b) {
  return a.type == b.type && a.texture_kind == b.texture_kind && a.storage_format == b.storage_format;
}

using BindingKey = std::pair<uint32_t, uint32_t>;  // set, binding
using MergedBindings = std::map<BindingKey, LayoutEntry>;

// Adds one stage's binding; a binding another stage declared already must match it.
void merge(MergedBindings& merged, const DeclaredBinding& declared, std::string_view label) {
  const auto [found, inserted] = merged.try_emplace({declared.set, declared.entry.binding}, declared.entry);
  LayoutEntry& entry = found->second;
  if (inserted) return;
  if (!same_resource(entry, declared.entry)) {
    throw std::runtime_error(std::string(label) + ": set " + std::to_string(declared.set) + ", binding " +
                             std::to_string(entry.binding) + " declared differently: " + stage_names(entry.visibility) +
                             " shader: " + describe(entry) + "; " + stage_names(declared.entry.visibility) +
                             " shader: " + describe(declared.entry));
  }
  entry.visibility |= declared.entry.visibility;
  entry.filtered = entry.filtered || declared.entry.filtered;
  if (entry.storage_access != declared.entry.storage_access) entry.storage_access = StorageAccess::read_write;
}

void merge_stage(MergedBindings& merged, const ShaderStageCode& code, std::string_view label) {
  const Module module = read_module(code.spirv);
  check_entry_point(module, code.stage, label);
  for (const Instruction& variable : module.variables) {
    const std::optional<DeclaredBinding> declared = reflect_variable(module, variable, code.stage, label);
    if (declared) merge(merged, *declared, label);
  }
}

// The map is ordered by set, then binding: entries arrive sorted.
std::vector<BindGroupLayoutDesc> layouts_of(const MergedBindings& merged, std::string_view label) {
  std::vector<BindGroupLayoutDesc> layouts;
  for (const auto& [key, entry] : merged) {
    while (layouts.size() <= key.first) {
      layouts.push_back({std::string(label) + " set " + std::to_string(layouts.size()), {}});
    }
    layouts[key.first].entries.push_back(entry);
  }
  return layouts;
}

}  // namespace

std::vector<BindGroupLayoutDesc> reflect_bind_group_layouts(std::span<const ShaderStageCode> stages,
                                                            std::string_view label) {
  MergedBindings merged;
  for (const ShaderStageCode& code : stages) merge_stage(merged, code, label);
  return layouts_of(merged, label);
}

// OpExecutionMode: Entry Point, Mode, then the mode's literals (LocalSize: x, y, z).
std::array<uint32_t, 3> reflect_workgroup_size(std::span<const uint32_t> spirv) {
  for (const Instruction& instruction : parse_instructions(spirv)) {
    if (instruction.opcode != op::execution_mode || operand(instruction, 1) != kExecutionModeLocalSize) continue;
    return {operand(instruction, 2), operand(instruction, 3), operand(instruction, 4)};
  }
  throw std::runtime_error("SPIR-V: no LocalSize execution mode with literal sizes");
}

}  // namespace volgraph::rhi
