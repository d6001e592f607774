// The declaration of a pass type: what a user may wire, set and swap.
// Each pass file builds one PassDecl as a table: variants, parameters, slots, needs.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "graph/access.h"
#include "graph/config/diagnostics.h"
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
  std::vector<std::string> needs_inputs = {};  // optional input slots this variant requires wired
};

enum class SlotDirection : uint8_t {
  input,   // reads a resource another pass made
  output,  // creates a resource
  inout,   // modifies a resource another pass made; downstream sees the new version
  history, // reads the previous frame's content of one of the pass's own outputs (its
           // `history_of`); bound by the graph, never wired (see slot_history)
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
  std::string doc;
};

// What is wrong with a pass's parameters given the scene; `param` names the parameter
// the message is about ("" for the pass as a whole).
struct ParamProblem {
  std::string param;
  std::string message;
  std::optional<Where> where = std::nullopt;  // set when the problem is elsewhere in the config (a scene object)
};

struct PassDecl;
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
  SceneFeatures needs = 0;
  SceneCheck check_scene = nullptr;      // optional
  MakeExecution make_execution = nullptr;  // none: the pass cannot run yet
  // Its execution keeps a bind group per PassContext::parity(), so it may bind the
  // resources of a history pair, whose objects swap every frame (the executor refuses
  // to run other passes on them: they would keep binding frame 0's objects).
  bool parity_bind_groups = false;

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

std::string_view pass_kind_name(PassKind kind);
std::string_view param_type_name(ParamType type);
std::string param_value_text(const ParamValue& value);

}  // namespace volgraph
