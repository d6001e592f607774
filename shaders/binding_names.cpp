// Build-time generator (shaders/CMakeLists.txt): reads one shader's SPIR-V and writes a
// header with one rhi::ShaderBinding per resource variable it declares, so that passes name
// bindings as the GLSL does (graph/rhi/bind_by_name.h).
//   volgraph_binding_names <shader.spv> <namespace> <header.h> [STRUCT=HEADER ...]
// Names: a uniform or storage buffer's instance name; without one, the name of its only
// member where that member is a struct (`uniform VignetteBlock { VignetteParams params; };`
// → params), else its block name; a texture's, storage image's or sampler's variable name.
// STRUCT=HEADER: a struct written once for GLSL and C++ (GPU_STRUCT in a header under
// shaders/include/, shaders/include/gpu_struct.h); the header includes it and asserts, at
// compile time, that the C++ struct's size and every member's offset (and an array's size)
// are the shader's, wherever a block of the shader holds it. Reflection by SPIRV-Cross's C
// API. Exit 2 with one message naming the file on bad input; nothing is written then.
#include <spirv_cross/spirv_cross_c.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

struct Variable {
  uint32_t set = 0;
  uint32_t binding = 0;
  std::string name;
};

// What the shader's SPIR-V says of one member of a shared struct.
struct MemberLayout {
  std::string name;
  uint64_t offset = 0;
  uint64_t array_bytes = 0;  // 0: not an array (or a runtime array)
};

// A struct some block of the shader holds, laid out as that block's rules say.
struct StructLayout {
  std::string name;
  uint64_t size = 0;          // the declared size, rounded up to 16 under std140
  bool size_is_known = true;  // std430's own struct alignment: the size is not checked
  std::vector<MemberLayout> members;
};

struct Reflection {
  std::vector<Variable> variables;
  std::map<std::string, StructLayout> structs;
};

std::vector<uint32_t> read_words(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read it");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.empty() || bytes.size() % 4 != 0) throw std::runtime_error("expected SPIR-V words (a multiple of 4 bytes)");
  std::vector<uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

void check(spvc_context context, spvc_result result) {
  if (result != SPVC_SUCCESS) throw std::runtime_error(std::string("SPIRV-Cross: ") + spvc_context_get_last_error_string(context));
}

// The kinds that take a (set, binding); the project's shaders declare no others
// (graph/rhi/spirv_reflect.cpp rejects the rest when a program is made).
constexpr spvc_resource_type kBoundKinds[] = {
    SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, SPVC_RESOURCE_TYPE_STORAGE_BUFFER,    SPVC_RESOURCE_TYPE_STORAGE_IMAGE,
    SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, SPVC_RESOURCE_TYPE_SAMPLED_IMAGE,
};

bool is_block(spvc_resource_type kind) {
  return kind == SPVC_RESOURCE_TYPE_UNIFORM_BUFFER || kind == SPVC_RESOURCE_TYPE_STORAGE_BUFFER;
}

uint64_t round_up(uint64_t v, uint64_t to) { return (v + to - 1) / to * to; }

// Records struct `type_id` and the structs inside it (a member's, or an array's element's).
void collect_struct(spvc_context context, spvc_compiler compiler, spvc_type_id type_id, bool std140,
                    std::map<std::string, StructLayout>& structs) {
  const spvc_type type = spvc_compiler_get_type_handle(compiler, type_id);
  const std::string name = spvc_compiler_get_name(compiler, spvc_type_get_base_type_id(type));
  if (spvc_type_get_basetype(type) != SPVC_BASETYPE_STRUCT || name.empty() || structs.contains(name)) return;
  StructLayout layout{name};
  size_t declared = 0;
  check(context, spvc_compiler_get_declared_struct_size(compiler, type, &declared));
  layout.size = std140 ? round_up(declared, 16) : declared;
  layout.size_is_known = std140;
  const unsigned count = spvc_type_get_num_member_types(type);
  for (unsigned i = 0; i < count; ++i) {
    MemberLayout member{spvc_compiler_get_member_name(compiler, spvc_type_get_base_type_id(type), i)};
    unsigned offset = 0;
    check(context, spvc_compiler_type_struct_member_offset(compiler, type, i, &offset));
    member.offset = offset;
    const spvc_type_id member_id = spvc_type_get_member_type(type, i);
    const spvc_type member_type = spvc_compiler_get_type_handle(compiler, member_id);
    if (spvc_type_get_num_array_dimensions(member_type) == 1 && spvc_type_array_dimension_is_literal(member_type, 0) &&
        spvc_type_get_array_dimension(member_type, 0) > 0) {
      unsigned stride = 0;
      check(context, spvc_compiler_type_struct_member_array_stride(compiler, type, i, &stride));
      member.array_bytes = uint64_t(stride) * spvc_type_get_array_dimension(member_type, 0);
    }
    layout.members.push_back(member);
    collect_struct(context, compiler, member_id, std140, structs);
  }
  structs[name] = layout;
}

// Sorted by set, then binding; one name per variable.
Reflection reflect(const std::vector<uint32_t>& words) {
  spvc_context context = nullptr;
  if (spvc_context_create(&context) != SPVC_SUCCESS) throw std::runtime_error("cannot create a SPIRV-Cross context");
  std::unique_ptr<std::remove_pointer_t<spvc_context>, void (*)(spvc_context)> owner(context, spvc_context_destroy);
  spvc_parsed_ir ir = nullptr;
  spvc_compiler compiler = nullptr;
  spvc_resources resources = nullptr;
  check(context, spvc_context_parse_spirv(context, words.data(), words.size(), &ir));
  check(context, spvc_context_create_compiler(context, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler));
  check(context, spvc_compiler_create_shader_resources(compiler, &resources));
  std::map<std::pair<uint32_t, uint32_t>, std::string> found;
  Reflection reflection;
  for (const spvc_resource_type kind : kBoundKinds) {
    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    check(context, spvc_resources_get_resource_list_for_type(resources, kind, &list, &count));
    for (size_t i = 0; i < count; ++i) {
      const uint32_t set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
      const uint32_t binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
      // A block's reflected name is its block name; its variable's is the instance name ("" when none).
      const std::string instance = spvc_compiler_get_name(compiler, list[i].id);
      std::string name = is_block(kind) && !instance.empty() ? instance : std::string(list[i].name);
      if (is_block(kind)) {
        const spvc_type block = spvc_compiler_get_type_handle(compiler, list[i].base_type_id);
        const bool std140 = kind == SPVC_RESOURCE_TYPE_UNIFORM_BUFFER;
        for (unsigned m = 0; m < spvc_type_get_num_member_types(block); ++m) {
          collect_struct(context, compiler, spvc_type_get_member_type(block, m), std140, reflection.structs);
        }
        const bool holds_one_struct = spvc_type_get_num_member_types(block) == 1 &&
            spvc_type_get_basetype(spvc_compiler_get_type_handle(compiler, spvc_type_get_member_type(block, 0))) == SPVC_BASETYPE_STRUCT;
        if (instance.empty() && holds_one_struct) name = spvc_compiler_get_member_name(compiler, list[i].base_type_id, 0);
      }
      found[{set, binding}] = name;
    }
  }
  for (const auto& [key, name] : found) reflection.variables.push_back({key.first, key.second, name});
  return reflection;
}

// The compile-time checks of the shared structs this shader holds in its blocks.
void write_struct_checks(std::ostream& out, const std::string& shader, const std::map<std::string, StructLayout>& structs,
                         const std::map<std::string, std::string>& shared_headers) {
  for (const auto& [name, layout] : structs) {
    const auto header = shared_headers.find(name);
    if (header == shared_headers.end()) continue;
    const std::string type = "::volgraph::gpu::" + name;
    out << "\n// " << name << " (" << header->second << ") as " << shader << " lays it out.\n";
    if (layout.size_is_known) {
      out << "static_assert(sizeof(" << type << ") == " << layout.size << ", \"" << name << ": " << shader
          << " takes " << layout.size << " bytes (std140); a vec3 or a scalar array pads otherwise in GLSL\");\n";
    }
    for (const MemberLayout& m : layout.members) {
      out << "static_assert(offsetof(" << type << ", " << m.name << ") == " << m.offset << ", \"" << name << "::" << m.name
          << ": " << shader << " puts it at byte " << m.offset << "\");\n";
      if (m.array_bytes > 0) {
        out << "static_assert(sizeof(" << type << "::" << m.name << ") == " << m.array_bytes << ", \"" << name << "::" << m.name
            << ": " << shader << "'s array takes " << m.array_bytes << " bytes (its stride × its length)\");\n";
      }
    }
  }
}

std::string header(const std::string& space, const std::string& spirv_path, const Reflection& reflection,
                   const std::map<std::string, std::string>& shared_headers) {
  const std::string shader = std::filesystem::path(spirv_path).stem().string();
  std::ostringstream out;
  out << "// Generated by volgraph_binding_names (shaders/binding_names.cpp) from "
      << std::filesystem::path(spirv_path).filename().string() << ": do not edit.\n"
      << "#pragma once\n\n#include <cstddef>\n\n#include \"graph/rhi/shader_binding.h\"\n";
  std::map<std::string, bool> included;
  for (const auto& [name, layout] : reflection.structs) {
    const auto found = shared_headers.find(name);
    if (found != shared_headers.end() && !included[found->second]) {
      out << "#include \"" << found->second << "\"\n";
      included[found->second] = true;
    }
  }
  out << "\nnamespace volgraph::shaders::" << space << " {\n";
  for (const Variable& v : reflection.variables) {
    out << "inline constexpr rhi::ShaderBinding " << v.name << "{" << v.set << ", " << v.binding << ", \"" << v.name << "\"};\n";
  }
  out << "}  // namespace volgraph::shaders::" << space << "\n";
  write_struct_checks(out, shader, reflection.structs, shared_headers);
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: volgraph_binding_names <shader.spv> <namespace> <header.h> [STRUCT=HEADER ...]\n";
    return 2;
  }
  std::map<std::string, std::string> shared_headers;
  for (int i = 4; i < argc; ++i) {
    const std::string pair = argv[i];
    const size_t equals = pair.find('=');
    if (equals == std::string::npos || equals == 0) {
      std::cerr << "volgraph_binding_names: expected STRUCT=HEADER, got \"" << pair << "\"\n";
      return 2;
    }
    shared_headers[pair.substr(0, equals)] = pair.substr(equals + 1);
  }
  std::string text;
  try {
    text = header(argv[2], argv[1], reflect(read_words(argv[1])), shared_headers);
  } catch (const std::exception& e) {
    std::cerr << argv[1] << ": " << e.what() << "\n";
    return 2;
  }
  std::ofstream(argv[3], std::ios::binary) << text;
  return 0;
}
