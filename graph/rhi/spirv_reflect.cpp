// SPIR-V reflection (spirv_reflect.h) through SPIRV-Cross's C API: it parses the module
// and lists its resources with their decorations and types, its entry points, execution
// modes and uniform block layouts. Two things are still read from the words here, in a
// small scan: the module's framing (so that a malformed module's error says where), and
// which textures and samplers an instruction samples through (`filtered`), which SPIRV-Cross
// does not tell (see "Filtering" below). § names a section of the SPIR-V specification.
#include "graph/rhi/spirv_reflect.h"

#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace volgraph::rhi {
namespace {

constexpr size_t kHeaderWords = 5;  // §2.3 Physical Layout of a SPIR-V Module and Instruction
constexpr uint32_t kMaxSets = 4;    // DESIGN.md: at most 4 descriptor sets (WebGPU)

// ---- The word stream ---------------------------------------------------------------

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

// §2.3: five header words, then instructions whose first word holds the word count (high
// 16 bits) and the opcode (low 16 bits). SPIRV-Cross checks this too, but does not say where.
std::vector<Instruction> parse_instructions(std::span<const uint32_t> spirv) {
  if (spirv.size() < kHeaderWords || spirv[0] != SpvMagicNumber) {
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

// ---- Filtering: which textures and samplers some instruction samples through ----------
// Hand-written because SPIRV-Cross cannot tell: its combined image samplers
// (spvc_compiler_build_combined_image_samplers) pair a texture with a sampler wherever an
// OpSampledImage joins them, and texelFetch(sampler2D(t, s), …) joins them too
// (OpSampledImage, then OpImage, then OpImageFetch). So this scan starts from the sampling
// instructions and follows their sampled image back to the variables it is made of.

// §3.32.10: the instructions that sample (filter) through a sampled image, their operand 2.
bool samples_through(uint32_t opcode) {
  switch (opcode) {
    case SpvOpImageSampleImplicitLod:
    case SpvOpImageSampleExplicitLod:
    case SpvOpImageSampleDrefImplicitLod:
    case SpvOpImageSampleDrefExplicitLod:
    case SpvOpImageSampleProjImplicitLod:
    case SpvOpImageSampleProjExplicitLod:
    case SpvOpImageSampleProjDrefImplicitLod:
    case SpvOpImageSampleProjDrefExplicitLod:
    case SpvOpImageGather:
    case SpvOpImageDrefGather:
    case SpvOpImageQueryLod:
    case SpvOpImageSparseSampleImplicitLod:
    case SpvOpImageSparseSampleExplicitLod:
    case SpvOpImageSparseSampleDrefImplicitLod:
    case SpvOpImageSparseSampleDrefExplicitLod:
    case SpvOpImageSparseGather:
    case SpvOpImageSparseDrefGather: return true;
    default: return false;
  }
}

struct FunctionCall {
  uint32_t function = 0;
  std::span<const uint32_t> arguments;
};

// What the scan collects: where each id's value comes from (an OpLoad's result from its
// pointer, an OpSampledImage's from its image and its sampler), each function's parameters
// in order, every call, and the sampled images that some instruction samples through.
struct SamplingScan {
  std::unordered_map<uint32_t, std::vector<uint32_t>> sources;
  std::unordered_map<uint32_t, std::vector<uint32_t>> parameters;
  std::vector<FunctionCall> calls;
  std::vector<uint32_t> sampled;
  uint32_t current_function = 0;
};

// Operands (§3.32.8, §3.32.9, §3.32.10): OpFunction: Result Type, Result, …;
// OpFunctionParameter: Result Type, Result; OpFunctionCall: Result Type, Result, Function,
// Arguments…; OpLoad: Result Type, Result, Pointer; OpSampledImage: Result Type, Result,
// Image, Sampler; a sampling instruction: Result Type, Result, Sampled Image, ….
void record(SamplingScan& scan, const Instruction& instruction) {
  switch (instruction.opcode) {
    case SpvOpFunction: scan.current_function = operand(instruction, 1); return;
    case SpvOpFunctionParameter: scan.parameters[scan.current_function].push_back(operand(instruction, 1)); return;
    case SpvOpFunctionCall:
      scan.calls.push_back({operand(instruction, 2), instruction.operands.subspan(3)});
      return;
    case SpvOpLoad: scan.sources[operand(instruction, 1)].push_back(operand(instruction, 2)); return;
    case SpvOpSampledImage:
      scan.sources[operand(instruction, 1)] = {operand(instruction, 2), operand(instruction, 3)};
      return;
    default:
      if (samples_through(instruction.opcode)) scan.sampled.push_back(operand(instruction, 2));
      return;
  }
}

// A parameter's value comes from every argument a call passes there (calls may come
// before the function they call, so this runs after the scan).
void add_parameter_sources(SamplingScan& scan) {
  for (const FunctionCall& call : scan.calls) {
    const std::vector<uint32_t>& parameters = scan.parameters[call.function];
    const size_t count = std::min(parameters.size(), call.arguments.size());
    for (size_t i = 0; i < count; ++i) scan.sources[parameters[i]].push_back(call.arguments[i]);
  }
}

// Every id some sampling instruction's sampled image is made of, followed back through
// loads, OpSampledImage and function parameters: the texture and sampler variables among
// them are the filtered ones.
std::set<uint32_t> ids_sampled_through(std::span<const Instruction> instructions) {
  SamplingScan scan;
  for (const Instruction& instruction : instructions) record(scan, instruction);
  add_parameter_sources(scan);
  std::set<uint32_t> reached;
  std::vector<uint32_t> pending = scan.sampled;
  while (!pending.empty()) {
    const uint32_t id = pending.back();
    pending.pop_back();
    if (!reached.insert(id).second) continue;
    const auto found = scan.sources.find(id);
    if (found != scan.sources.end()) pending.insert(pending.end(), found->second.begin(), found->second.end());
  }
  return reached;
}

// ---- One module, parsed by SPIRV-Cross ----------------------------------------------

struct ContextDeleter {
  void operator()(spvc_context context) const { spvc_context_destroy(context); }
};

// A module's instructions (framing checked) and a reflection-only SPIRV-Cross compiler
// over it. The context owns everything SPIRV-Cross hands out: the resource lists and names
// stay valid while the Module lives. Throws std::runtime_error where SPIRV-Cross fails.
class Module {
 public:
  explicit Module(std::span<const uint32_t> spirv) : instructions_(parse_instructions(spirv)) {
    spvc_context context = nullptr;
    if (spvc_context_create(&context) != SPVC_SUCCESS) {
      throw std::runtime_error("SPIR-V: cannot create a SPIRV-Cross context");
    }
    context_.reset(context);
    spvc_parsed_ir ir = nullptr;
    check(spvc_context_parse_spirv(context, spirv.data(), spirv.size(), &ir));
    check(spvc_context_create_compiler(context, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler_));
    check(spvc_compiler_create_shader_resources(compiler_, &resources_));
  }

  std::span<const Instruction> instructions() const { return instructions_; }

  // Every declared resource of one SPIRV-Cross kind, used by the entry point or not.
  std::span<const spvc_reflected_resource> resources(spvc_resource_type type) const {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    check(spvc_resources_get_resource_list_for_type(resources_, type, &list, &count));
    return {list, count};
  }

  std::span<const spvc_entry_point> entry_points() const {
    const spvc_entry_point* entries = nullptr;
    size_t count = 0;
    check(spvc_compiler_get_entry_points(compiler_, &entries, &count));
    return {entries, count};
  }

  // Reflection of execution modes (and of which variables are used) is per entry point.
  void use_entry_point(const spvc_entry_point& entry) {
    check(spvc_compiler_set_entry_point(compiler_, entry.name, entry.execution_model));
  }

  bool has_execution_mode(SpvExecutionMode mode) const {
    const SpvExecutionMode* modes = nullptr;
    size_t count = 0;
    check(spvc_compiler_get_execution_modes(compiler_, &modes, &count));
    return std::ranges::count(std::span(modes, count), mode) > 0;
  }

  uint32_t execution_mode_argument(SpvExecutionMode mode, uint32_t index) const {
    return spvc_compiler_get_execution_mode_argument_by_index(compiler_, mode, index);
  }

  spvc_type type(spvc_type_id id) const { return spvc_compiler_get_type_handle(compiler_, id); }

  bool has_decoration(SpvId id, SpvDecoration decoration) const {
    return spvc_compiler_has_decoration(compiler_, id, decoration) == SPVC_TRUE;
  }

  uint32_t decoration(SpvId id, SpvDecoration decoration) const {
    return spvc_compiler_get_decoration(compiler_, id, decoration);
  }

  // A buffer variable's decorations, with those that all of its block's members carry.
  bool buffer_block_has(spvc_variable_id variable, SpvDecoration decoration) const {
    const SpvDecoration* decorations = nullptr;
    size_t count = 0;
    check(spvc_compiler_get_buffer_block_decorations(compiler_, variable, &decorations, &count));
    return std::ranges::count(std::span(decorations, count), decoration) > 0;
  }

  uint64_t struct_size(spvc_type block) const {
    size_t size = 0;
    check(spvc_compiler_get_declared_struct_size(compiler_, block, &size));
    return size;
  }

  uint64_t member_size(spvc_type block, uint32_t member) const {
    size_t size = 0;
    check(spvc_compiler_get_declared_struct_member_size(compiler_, block, member, &size));
    return size;
  }

  uint64_t member_offset(spvc_type block, uint32_t member) const {
    unsigned offset = 0;
    check(spvc_compiler_type_struct_member_offset(compiler_, block, member, &offset));
    return offset;
  }

  // "" when the module does not name it.
  std::string member_name(spvc_type_id block, uint32_t member) const {
    const char* name = spvc_compiler_get_member_name(compiler_, block, member);
    return name == nullptr ? "" : name;
  }

  // The specialisation constants a compute shader's workgroup size comes from (id 0: a literal).
  std::array<spvc_specialization_constant, 3> workgroup_size_constants() const {
    std::array<spvc_specialization_constant, 3> constants{};
    spvc_compiler_get_work_group_size_specialization_constants(compiler_, &constants[0], &constants[1], &constants[2]);
    return constants;
  }

 private:
  void check(spvc_result result) const {
    if (result == SPVC_SUCCESS) return;
    throw std::runtime_error(std::string("SPIR-V: ") + spvc_context_get_last_error_string(context_.get()));
  }

  std::vector<Instruction> instructions_;
  std::unique_ptr<spvc_context_s, ContextDeleter> context_;
  spvc_compiler compiler_ = nullptr;
  spvc_resources resources_ = nullptr;
};

// ---- Names for error messages -------------------------------------------------------

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
  if (is_texture && entry.cube_faces) text += " faces";
  if (entry.type == BindingType::storage_texture) text += " " + std::string(format_info(entry.storage_format).name);
  return text;
}

// "uniform block Params (48 bytes: modes at 0, lobes at 16, volumetric at 32)".
std::string describe(const UniformBlockLayout& block) {
  std::string text = "uniform block " + block.name + " (" + std::to_string(block.size) + " bytes";
  for (size_t i = 0; i < block.members.size(); ++i) {
    text += (i == 0 ? ": " : ", ") + block.members[i].name + " at " + std::to_string(block.members[i].offset);
  }
  return text + ")";
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

// "conflict: set 1, binding 2 declared differently: vertex shader: uniform buffer; fragment
// shader: sampled texture texture2d".
[[noreturn]] void fail_conflict(std::string_view label, uint32_t set, uint32_t binding, uint32_t first_stages,
                                const std::string& first, uint32_t second_stages, const std::string& second) {
  throw std::runtime_error(std::string(label) + ": set " + std::to_string(set) + ", binding " +
                           std::to_string(binding) + " declared differently: " + stage_names(first_stages) +
                           " shader: " + first + "; " + stage_names(second_stages) + " shader: " + second);
}

// ---- One stage ------------------------------------------------------------------------

SpvExecutionModel execution_model_of(uint32_t stage, std::string_view label) {
  switch (stage) {
    case shader_stage::vertex: return SpvExecutionModelVertex;
    case shader_stage::fragment: return SpvExecutionModelFragment;
    case shader_stage::compute: return SpvExecutionModelGLCompute;
    default: fail(label, stage, "stage bits " + std::to_string(stage) + " are not one shader_stage bit");
  }
}

// Parses one stage's module and makes its entry point of that stage the one reflected.
Module read_stage(const ShaderStageCode& code, std::string_view label) {
  Module module(code.spirv);
  const SpvExecutionModel model = execution_model_of(code.stage, label);
  for (const spvc_entry_point& entry : module.entry_points()) {
    if (entry.execution_model != model) continue;
    module.use_entry_point(entry);
    return module;
  }
  fail(label, code.stage, "the module has no entry point of that stage");
}

// A resource's set and binding, checked: both declared, the set below kMaxSets, no array.
Where where_of(const Module& module, const spvc_reflected_resource& resource, uint32_t stage, std::string_view label) {
  const bool bound = module.has_decoration(resource.id, SpvDecorationDescriptorSet) &&
                     module.has_decoration(resource.id, SpvDecorationBinding);
  if (!bound) fail(label, stage, "a resource without DescriptorSet and Binding");
  const Where where{label, stage, module.decoration(resource.id, SpvDecorationDescriptorSet),
                    module.decoration(resource.id, SpvDecorationBinding)};
  if (where.set >= kMaxSets) where.fail("at most " + std::to_string(kMaxSets) + " sets (0 to 3)");
  if (spvc_type_get_num_array_dimensions(module.type(resource.type_id)) > 0) {
    where.fail("arrays of resources are not supported: one resource per binding");
  }
  return where;
}

// ---- Bind group layout entries -------------------------------------------------------

// §3.11 Image Format: the SPIR-V formats volgraph has a Format for.
constexpr std::pair<SpvImageFormat, Format> kImageFormats[] = {
    {SpvImageFormatRgba32f, Format::rgba32_float},        {SpvImageFormatRgba16f, Format::rgba16_float},
    {SpvImageFormatR32f, Format::r32_float},              {SpvImageFormatRgba8, Format::rgba8_unorm},
    {SpvImageFormatRg32f, Format::rg32_float},            {SpvImageFormatRg16f, Format::rg16_float},
    {SpvImageFormatR11fG11fB10f, Format::r11g11b10_float}, {SpvImageFormatR16f, Format::r16_float},
    {SpvImageFormatR8, Format::r8_unorm},                 {SpvImageFormatR32ui, Format::r32_uint},
};

// A 2D array is read as a cube's six faces (the only arrayed textures the graph makes).
ResourceKind image_kind(SpvDim dim, bool arrayed, const Where& where) {
  if (arrayed && dim != SpvDim2D) where.fail("arrayed images other than a cube's faces (2D arrays) are not supported");
  if (dim == SpvDim2D) return arrayed ? ResourceKind::texture_cube : ResourceKind::texture2d;
  if (dim == SpvDim3D) return ResourceKind::texture3d;
  if (dim == SpvDimCube) return ResourceKind::texture_cube;
  where.fail("image Dim " + std::to_string(dim) + " is neither 2D, 3D nor Cube");
}

Format storage_format(SpvImageFormat image_format, const Where& where) {
  const auto* known = std::ranges::find(kImageFormats, image_format, &std::pair<SpvImageFormat, Format>::first);
  const bool mapped = known != std::end(kImageFormats);
  if (mapped && format_info(known->second).storage_capable) return known->second;
  where.fail("storage image format " + std::to_string(image_format) +
             " (SPIR-V Image Format) is not a storage format of both backends");
}

// A separate texture or a storage image: 2D, 3D, a cube or its faces as a 2D array; not multisampled.
LayoutEntry image_entry(spvc_type image, BindingType type, const Where& where) {
  if (spvc_type_get_image_multisampled(image)) where.fail("multisampled images are not supported");
  const bool arrayed = spvc_type_get_image_arrayed(image);
  LayoutEntry entry{.type = type, .texture_kind = image_kind(spvc_type_get_image_dimension(image), arrayed, where), .cube_faces = arrayed};
  if (type == BindingType::storage_texture) {
    entry.storage_format = storage_format(spvc_type_get_image_storage_format(image), where);
  }
  return entry;
}

// A storage buffer is read-only when the variable, or every member of its block, is NonWritable.
LayoutEntry storage_buffer_entry(const Module& module, const spvc_reflected_resource& resource) {
  const bool read_only = module.buffer_block_has(resource.id, SpvDecorationNonWritable);
  return {.type = read_only ? BindingType::read_only_storage_buffer : BindingType::storage_buffer};
}

// The entry of one resource of SPIRV-Cross's kind `kind`; what the rhi cannot express throws.
LayoutEntry resource_entry(const Module& module, spvc_resource_type kind, const spvc_reflected_resource& resource,
                           const Where& where) {
  switch (kind) {
    case SPVC_RESOURCE_TYPE_UNIFORM_BUFFER: return {.type = BindingType::uniform_buffer};
    case SPVC_RESOURCE_TYPE_STORAGE_BUFFER: return storage_buffer_entry(module, resource);
    case SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS: return {.type = BindingType::sampler};
    case SPVC_RESOURCE_TYPE_SEPARATE_IMAGE:
      return image_entry(module.type(resource.base_type_id), BindingType::sampled_texture, where);
    case SPVC_RESOURCE_TYPE_STORAGE_IMAGE:
      return image_entry(module.type(resource.base_type_id), BindingType::storage_texture, where);
    case SPVC_RESOURCE_TYPE_SAMPLED_IMAGE:
      where.fail("combined image samplers are not supported: declare a texture and a sampler");
    case SPVC_RESOURCE_TYPE_SUBPASS_INPUT: where.fail("subpass inputs are not supported");
    case SPVC_RESOURCE_TYPE_ATOMIC_COUNTER: where.fail("atomic counters are not supported");
    case SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE: where.fail("acceleration structures are not supported");
    default: where.fail("unsupported resource (SPIRV-Cross resource type " + std::to_string(kind) + ")");
  }
}

// The SPIRV-Cross resource kinds that take a binding (push constants are rejected before).
constexpr spvc_resource_type kBoundResourceKinds[] = {
    SPVC_RESOURCE_TYPE_UNIFORM_BUFFER,  SPVC_RESOURCE_TYPE_STORAGE_BUFFER,    SPVC_RESOURCE_TYPE_STORAGE_IMAGE,
    SPVC_RESOURCE_TYPE_SEPARATE_IMAGE,  SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, SPVC_RESOURCE_TYPE_SAMPLED_IMAGE,
    SPVC_RESOURCE_TYPE_SUBPASS_INPUT,   SPVC_RESOURCE_TYPE_ATOMIC_COUNTER,    SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE,
};

// A resource variable's set and its entry (visible to `stage`).
struct DeclaredBinding {
  uint32_t set = 0;
  LayoutEntry entry;
};

DeclaredBinding declared_binding(const Module& module, spvc_resource_type kind, const spvc_reflected_resource& resource,
                                 const std::set<uint32_t>& sampled_through, uint32_t stage, std::string_view label) {
  const Where where = where_of(module, resource, stage, label);
  LayoutEntry entry = resource_entry(module, kind, resource, where);
  entry.binding = where.binding;
  entry.visibility = stage;
  entry.filtered = sampled_through.contains(resource.id);
  if (module.has_decoration(resource.id, SpvDecorationNonWritable)) entry.storage_access = StorageAccess::read_only;
  if (module.has_decoration(resource.id, SpvDecorationNonReadable)) entry.storage_access = StorageAccess::write_only;
  return {where.set, entry};
}

// Every resource one stage declares, push constants rejected.
std::vector<DeclaredBinding> declared_bindings(const Module& module, uint32_t stage, std::string_view label) {
  if (!module.resources(SPVC_RESOURCE_TYPE_PUSH_CONSTANT).empty()) {
    fail(label, stage, "push constants are not supported: use a uniform buffer");
  }
  const std::set<uint32_t> sampled_through = ids_sampled_through(module.instructions());
  std::vector<DeclaredBinding> bindings;
  for (const spvc_resource_type kind : kBoundResourceKinds) {
    for (const spvc_reflected_resource& resource : module.resources(kind)) {
      bindings.push_back(declared_binding(module, kind, resource, sampled_through, stage, label));
    }
  }
  return bindings;
}

bool same_resource(const LayoutEntry& a, const LayoutEntry& b) {
  return a.type == b.type && a.texture_kind == b.texture_kind && a.cube_faces == b.cube_faces && a.storage_format == b.storage_format;
}

using BindingKey = std::pair<uint32_t, uint32_t>;  // set, binding
using MergedBindings = std::map<BindingKey, LayoutEntry>;

// Adds one stage's binding; a binding another stage declared already must match it.
void merge(MergedBindings& merged, const DeclaredBinding& declared, std::string_view label) {
  const auto [found, inserted] = merged.try_emplace({declared.set, declared.entry.binding}, declared.entry);
  LayoutEntry& entry = found->second;
  if (inserted) return;
  if (!same_resource(entry, declared.entry)) {
    fail_conflict(label, declared.set, entry.binding, entry.visibility, describe(entry), declared.entry.visibility,
                  describe(declared.entry));
  }
  entry.visibility |= declared.entry.visibility;
  entry.filtered = entry.filtered || declared.entry.filtered;
  if (entry.storage_access != declared.entry.storage_access) entry.storage_access = StorageAccess::read_write;
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

// ---- Uniform block layouts ------------------------------------------------------------

// "member 2" where the module does not name it.
std::string member_name_or_index(const Module& module, spvc_type_id block, uint32_t member) {
  std::string name = module.member_name(block, member);
  return name.empty() ? "member " + std::to_string(member) : name;
}

// One uniform buffer's block, as SPIR-V lays it out (Offset decorations; std140 from glslang).
UniformBlockLayout block_layout(const Module& module, const spvc_reflected_resource& resource, const Where& where) {
  const spvc_type block = module.type(resource.base_type_id);
  UniformBlockLayout layout{.set = where.set,
                            .binding = where.binding,
                            .name = resource.name == nullptr ? "" : resource.name,
                            .size = module.struct_size(block),
                            .members = {}};
  const uint32_t member_count = spvc_type_get_num_member_types(block);
  for (uint32_t member = 0; member < member_count; ++member) {
    layout.members.push_back({.name = member_name_or_index(module, resource.base_type_id, member),
                              .offset = module.member_offset(block, member),
                              .size = module.member_size(block, member)});
  }
  return layout;
}

bool same_layout(const UniformBlockLayout& a, const UniformBlockLayout& b) {
  auto same_member = [](const UniformMember& x, const UniformMember& y) {
    return x.name == y.name && x.offset == y.offset && x.size == y.size;
  };
  return a.name == b.name && a.size == b.size && std::ranges::equal(a.members, b.members, same_member);
}

struct StagedBlock {
  UniformBlockLayout layout;
  uint32_t stages = 0;
};

// Adds one stage's block; a block another stage declared already must be laid out alike.
void merge_block(std::map<BindingKey, StagedBlock>& merged, UniformBlockLayout layout, uint32_t stage,
                 std::string_view label) {
  const BindingKey key{layout.set, layout.binding};
  const auto [found, inserted] = merged.try_emplace(key, StagedBlock{layout, stage});
  if (inserted) return;
  if (!same_layout(found->second.layout, layout)) {
    fail_conflict(label, key.first, key.second, found->second.stages, describe(found->second.layout), stage,
                  describe(layout));
  }
  found->second.stages |= stage;
}

// "Params (set 0, binding 5)".
std::string block_title(const UniformBlockLayout& block) {
  return block.name + " (set " + std::to_string(block.set) + ", binding " + std::to_string(block.binding) + ")";
}

}  // namespace

std::vector<BindGroupLayoutDesc> reflect_bind_group_layouts(std::span<const ShaderStageCode> stages,
                                                            std::string_view label) {
  MergedBindings merged;
  for (const ShaderStageCode& code : stages) {
    const Module module = read_stage(code, label);
    for (const DeclaredBinding& declared : declared_bindings(module, code.stage, label)) merge(merged, declared, label);
  }
  return layouts_of(merged, label);
}

std::array<uint32_t, 3> reflect_workgroup_size(std::span<const uint32_t> spirv) {
  const Module module(spirv);
  if (!module.has_execution_mode(SpvExecutionModeLocalSize)) {
    throw std::runtime_error("SPIR-V: no LocalSize execution mode with literal sizes");
  }
  for (const spvc_specialization_constant& constant : module.workgroup_size_constants()) {
    if (constant.id == 0) continue;
    throw std::runtime_error("SPIR-V: the workgroup size is given by specialisation constants (constant_id " +
                             std::to_string(constant.constant_id) + "), not literal sizes");
  }
  return {module.execution_mode_argument(SpvExecutionModeLocalSize, 0),
          module.execution_mode_argument(SpvExecutionModeLocalSize, 1),
          module.execution_mode_argument(SpvExecutionModeLocalSize, 2)};
}

std::vector<UniformBlockLayout> reflect_uniform_blocks(std::span<const ShaderStageCode> stages,
                                                       std::string_view label) {
  std::map<BindingKey, StagedBlock> merged;
  for (const ShaderStageCode& code : stages) {
    const Module module = read_stage(code, label);
    for (const spvc_reflected_resource& resource : module.resources(SPVC_RESOURCE_TYPE_UNIFORM_BUFFER)) {
      const Where where = where_of(module, resource, code.stage, label);
      merge_block(merged, block_layout(module, resource, where), code.stage, label);
    }
  }
  std::vector<UniformBlockLayout> blocks;
  for (auto& [key, staged] : merged) blocks.push_back(std::move(staged.layout));
  return blocks;
}

void check_uniform_block(const UniformBlockLayout& block, uint64_t host_size, std::span<const uint64_t> host_offsets,
                         std::string_view host_name) {
  const std::string differ = "host struct " + std::string(host_name) + " does not match uniform block " +
                             block_title(block) + ": ";
  if (host_offsets.size() != block.members.size()) {
    throw std::runtime_error(differ + "the block has " + std::to_string(block.members.size()) +
                             " members, the host struct " + std::to_string(host_offsets.size()));
  }
  for (size_t i = 0; i < host_offsets.size(); ++i) {
    const UniformMember& member = block.members[i];
    if (host_offsets[i] == member.offset) continue;
    throw std::runtime_error(differ + "member " + std::to_string(i) + " (" + member.name + ", " +
                             std::to_string(member.size) + " bytes) is at offset " + std::to_string(member.offset) +
                             " in the block, " + std::to_string(host_offsets[i]) + " in the host struct");
  }
  if (host_size != block.size) {
    throw std::runtime_error(differ + "the block is " + std::to_string(block.size) + " bytes, the host struct " +
                             std::to_string(host_size) + " (the sizes must be equal)");
  }
}

}  // namespace volgraph::rhi
