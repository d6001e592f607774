// The declaration of a pass type: what a user may wire, set and swap.
// Each pass file builds one PassDecl as a table: variants, parameters, slots, needs.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <string>
#include <variant>
#include <vector>

#include "graph/access.h"
#include "graph/diagnostics.h"
#include "graph/param_handle.h"
#include "graph/resource.h"
#include "graph/scene_features.h"

namespace volgraph {

struct Scene;
class PassExecution;

enum class ParamType : uint8_t { boolean, integer, number, vec3, choice };

using ParamValue = std::variant<bool, int64_t, double, std::array<double, 3>, std::string>;

struct ParamDecl {
  std::string name;
  ParamType type = ParamType::number;
  ParamValue default_value;
  double min = 0.0;  // integer, number, vec3 (each component)
  double max = 0.0;
  std::string unit;                  // "m", "1/m", "texels", "" for none
  std::vector<std::string> choices;  // choice
  std::string doc;
};

struct VariantDecl {
  std::string name;
  std::string doc;
  std::vector<std::string> needs_inputs = {};  // optional input slots this variant requires wired (SlotOptions::required_in)
  // What the variant changes in the pass's shader: a constant the pass hands its shader
  // (e.g. PHASE_HG from shaders/include/phase_codes.h, a header C++ and GLSL both read).
  int32_t shader_code = 0;
};

enum class SlotDirection : uint8_t {
  input,   // reads a resource another pass made
  output,  // creates a resource
  inout,   // modifies a resource another pass made; downstream sees the new version
  history, // reads the previous frame's content of one of the pass's own outputs (its
           // `history_of`); bound by the graph, never wired (see slot_history)
  internal, // a transient only the pass's own steps use (StepDecl): never wired; the graph
            // gives it memory and plans its barriers like any other, named "pass.slot"
};

struct SlotDecl {
  std::string name;
  SlotDirection direction = SlotDirection::input;
  ResourceKind kind = ResourceKind::texture2d;
  Usage usage = Usage::sampled;
  Format format = Format::undefined;  // outputs: the default; inputs: undefined = any
  SizeSpec size{};                    // outputs only
  bool optional = false;              // inputs: the pass runs without it
  bool persistent = false;            // outputs: kept across frames, never aliased
  bool format_overridable = false;    // outputs: config may choose another format
  bool size_overridable = false;      // outputs: config may choose another size
  std::string like;                   // outputs: take kind, format and size from this input slot
  std::string history_of;             // history: the output slot whose previous frame it reads
  std::vector<uint16_t> read_in;      // optional inputs: the variants that read it (empty: every one); wired in another, refused
  std::string doc;
};

// What is wrong with a pass's parameters given the scene; `param` names the parameter
// the message is about ("" for the pass as a whole).
struct ParamProblem {
  std::string param;
  std::string message;
  std::optional<Where> where = std::nullopt;  // set when the problem is elsewhere in the config (a scene object)
  bool warning = false;                       // accepted, but not drawn as the config asks (shown, not refused)
};

struct PassDecl;

// A step of a pass made of several (PassDecl::steps): one graph pass of its own, so the
// compiler orders it, plans the barriers between it and the other steps, and times it.
// It uses some of the pass's slots — inputs, outputs and internal slots — each with this
// step's usage; the first step that writes a slot makes it, later writers modify it.
//
// A step may run only in some of the pass's variants, and while an integer parameter
// exceeds a value (one step per layer of a technique with a layer count): the loader adds
// only the steps whose condition holds, so a step that does not run has no graph pass and
// the transients only it uses get no memory. The first step always runs (the graph pass
// of the config's pass), and so must every step that first writes a slot a later step
// uses under a weaker condition (registration checks).
struct StepCondition {
  std::vector<uint16_t> variants = {};  // empty: every variant
  int32_t count_param = -1;             // an integer parameter's index; -1: no count
  int64_t above = 0;                    // runs while that parameter's value exceeds this
  bool always() const { return variants.empty() && count_param < 0; }
  bool holds(uint16_t variant, const std::vector<ParamValue>& params) const;
};

struct StepDecl {
  std::string name;  // the graph pass is "<pass>/<name>"
  PassKind kind = PassKind::graphics;
  std::vector<std::pair<uint16_t, Usage>> uses;  // slot index (into PassDecl::slots), usage
  std::shared_ptr<const PassDecl> decl;          // made by finish_steps(): the step as a pass of its own
  StepCondition when = {};
};

// Checks a pass whose scene needs hold, with its parameter values (as decl.params).
using SceneCheck = std::vector<ParamProblem> (*)(const PassDecl& decl, const Scene& scene,
                                                 const std::vector<ParamValue>& params);

// Makes what a pass of this type does on the GPU (graph/execute/pass_execution.h).
// A function object, so a pass type may hand its executions objects they share.
using MakeExecution = std::function<std::unique_ptr<PassExecution>()>;

struct PassDecl {
  std::string name;
  PassKind kind = PassKind::compute;
  std::string doc;
  std::vector<VariantDecl> variants;  // first is the default; never empty
  std::vector<ParamDecl> params;
  std::vector<SlotDecl> slots;
  SceneFeatures needs = 0;      // every one of these scene features, else the pass is culled
  SceneFeatures needs_any = 0;  // at least one of these when not empty (needs_hold())
  SceneCheck check_scene = nullptr;      // optional
  MakeExecution make_execution = nullptr;  // none: the pass cannot run yet
  // Cached persistent outputs: when set, every output is persistent and a frame whose
  // cache key (graph/execute/cache_key.h: the pass's type, variant and parameters, the
  // scene parts below, and its inputs' keys) equals the last frame's skips the pass.
  bool cached = false;
  // The parts of the scene the pass's output depends on (its cache key and, through it,
  // its readers'). A pass that is not `frame_invariant` gets a new key every frame.
  ScenePartMask reads_scene = 0;
  // The output depends only on the key's contents, not on the frame number (no jitter,
  // no history): the pass's key then stays equal between frames.
  bool frame_invariant = false;
  // Empty: the pass is one graph pass. Else the steps it runs as, in order; they share
  // one execution (PassSetup::step_is() says which is recording).
  std::vector<StepDecl> steps;

  int variant_index(std::string_view variant) const;  // -1 when unknown
  int param_index(std::string_view param) const;
  int slot_index(std::string_view slot) const;
};

// Table helpers, so a pass reads as one declaration.
ParamDecl param_bool(std::string name, bool def, std::string doc);
ParamDecl param_int(std::string name, int64_t def, int64_t min, int64_t max, std::string unit, std::string doc);
ParamDecl param_number(std::string name, double def, double min, double max, std::string unit, std::string doc);
ParamDecl param_vec3(std::string name, std::array<double, 3> def, double min, double max, std::string unit,
                     std::string doc);
ParamDecl param_choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc);

SlotDecl slot_in(std::string name, ResourceKind kind, Usage usage, std::string doc);
SlotDecl slot_optional_in(std::string name, ResourceKind kind, Usage usage, std::string doc);
SlotDecl slot_out(std::string name, ResourceKind kind, Usage usage, Format format, SizeSpec size, std::string doc);
SlotDecl slot_out_like(std::string name, std::string input_slot, Usage usage, std::string doc);
SlotDecl slot_inout(std::string name, ResourceKind kind, Usage usage, std::string doc);
// Last frame's content of the pass's output `output_slot`, read (sampled) while this
// frame's is written: the output becomes persistent, and the graph gives it a twin
// resource of the same shape for the previous frame; the executor swaps the two
// physical objects every frame (a history pair). On the first frame the history holds
// nothing valid: the pass must know (PassContext::history_valid) and not read it.
SlotDecl slot_history(std::string name, std::string output_slot, std::string doc);

// Typed handles into a pass type's tables, returned by PassTable below: a pass keeps
// them, so its execution names a slot, parameter or variant by a member that must
// exist (a misspelt name does not compile) and reads a parameter as its own type
// (ParamHandle and ChoiceHandle: graph/param_handle.h, which SizeSpec uses too).
struct SlotHandle {
  uint16_t index = 0;
};
struct StepHandle {
  uint16_t index = 0;
  friend bool operator==(StepHandle, StepHandle) = default;
};
struct VariantHandle {
  uint16_t index = 0;
  friend bool operator==(VariantHandle, VariantHandle) = default;
};
// What a slot may add to its kind, usage and doc.
struct SlotOptions {
  Format format = Format::undefined;  // inputs: the format required (undefined: any); outputs: the default
  bool persistent = false;            // outputs: kept across frames, never aliased
  bool format_overridable = false;    // outputs: the config may choose another format
  bool size_overridable = false;      // outputs: the config may choose another size
  std::vector<VariantHandle> required_in = {};  // optional inputs: the variants that need it wired
  std::vector<VariantHandle> read_in = {};      // optional inputs: the only variants that read it (wired in another: refused)
};

// A pass type's declaration written as one table: a pass derives a struct from
// PassTable whose members, in order, are its variants, parameters and slots, each
// initialised by the call that declares it (so the table and the handles are one list):
//
//   struct FroxelScatterTable : PassTable {
//     FroxelScatterTable() : PassTable("froxel_scatter", PassKind::compute, "…") {}
//     VariantHandle hg = variant("hg", "Henyey–Greenstein", PHASE_HG);
//     ParamHandle<double> g_back = number("g_back", -0.3, -0.999, 0.999, "", "…");
//     SlotHandle media_scattering = input("media_scattering", ResourceKind::texture3d, Usage::sampled, "…");
//   };
//
// and registers it with pass_type<Table, Execution>() (graph/execute/pass_execution.h).
class PassTable {
 public:
  PassTable(std::string name, PassKind kind, std::string doc);
  PassDecl decl;

 protected:
  VariantHandle variant(std::string name, std::string doc, int32_t shader_code = 0);
  ParamHandle<bool> flag(std::string name, bool def, std::string doc);
  ParamHandle<int64_t> integer(std::string name, int64_t def, int64_t min, int64_t max, std::string unit, std::string doc);
  ParamHandle<double> number(std::string name, double def, double min, double max, std::string unit, std::string doc);
  ParamHandle<std::array<double, 3>> vec3(std::string name, std::array<double, 3> def, double min, double max,
                                          std::string unit, std::string doc);
  ParamHandle<std::string> choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc);
  template <typename Enum>
    requires std::is_enum_v<Enum>
  ChoiceHandle<Enum> choice(std::string name, Enum def, std::vector<std::pair<Enum, std::string>> choices, std::string doc) {
    std::vector<std::string> names;
    std::string def_name;
    for (const auto& [value, choice_name] : choices) {
      names.push_back(choice_name);
      if (value == def) def_name = choice_name;
    }
    return {choice(std::move(name), std::move(def_name), std::move(names), std::move(doc)), std::move(choices)};
  }
  SlotHandle input(std::string name, ResourceKind kind, Usage usage, std::string doc, SlotOptions options = {});
  SlotHandle optional_input(std::string name, ResourceKind kind, Usage usage, std::string doc, SlotOptions options = {});
  SlotHandle output(std::string name, ResourceKind kind, Usage usage, Format format, SizeSpec size, std::string doc,
                    SlotOptions options = {});
  SlotHandle output_like(std::string name, SlotHandle like, Usage usage, std::string doc);
  SlotHandle inout(std::string name, ResourceKind kind, Usage usage, std::string doc);
  SlotHandle history(std::string name, SlotHandle output, std::string doc);
  // A transient only this pass's steps use: its kind, format and size as an output's.
  SlotHandle internal(std::string name, ResourceKind kind, Format format, SizeSpec size, std::string doc);
  // A step and the slots it uses, with its usage of each; `when` says when it runs.
  StepHandle step(std::string name, PassKind kind, std::vector<std::pair<SlotHandle, Usage>> uses, StepCondition when = {});
  // Step conditions: in these variants; in this variant while `count` exceeds `above`.
  static StepCondition only_in(std::vector<VariantHandle> variants);
  static StepCondition only_in_while(VariantHandle variant, ParamHandle<int64_t> count, int64_t above);

 private:
  SlotHandle add_slot(SlotDecl slot, const SlotOptions& options);
  template <typename T>
  ParamHandle<T> add_param(ParamDecl param);
};

// Makes each step's PassDecl (StepDecl::decl) once the table is complete: the pass's
// variants, parameters, needs and slots (the same indices), each slot the step uses
// given the step's usage and direction — input for reads, output for the step that first
// writes a slot, inout for later writers. Throws std::logic_error where a conditional
// step would make a slot that a step running more often uses (StepCondition).
void finish_steps(PassDecl& decl);

// A parameter's value among a pass's values (as its decl lists them), by its handle:
// for scene checks, which see the values before an execution exists.
template <typename T>
const T& param_in(const std::vector<ParamValue>& values, ParamHandle<T> handle) {
  return std::get<T>(values.at(handle.index));
}

// The name a handle's parameter is declared with, for a scene check's ParamProblem::param
// (so the problem names the parameter the check read, never a second spelling of it).
template <typename T>
const std::string& param_name(const PassDecl& decl, ParamHandle<T> handle) {
  return decl.params.at(handle.index).name;
}

std::string_view pass_kind_name(PassKind kind);
std::string_view param_type_name(ParamType type);
std::string param_value_text(const ParamValue& value);

}  // namespace volgraph
