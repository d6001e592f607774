#include "graph/pass_decl.h"

#include <algorithm>
#include <stdexcept>

#include <cstdio>

namespace volgraph {
namespace {

template <typename T>
int index_by_name(const std::vector<T>& items, std::string_view name) {
  for (size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

int PassDecl::variant_index(std::string_view variant) const { return index_by_name(variants, variant); }
int PassDecl::param_index(std::string_view param) const { return index_by_name(params, param); }
int PassDecl::slot_index(std::string_view slot) const { return index_by_name(slots, slot); }

ParamDecl param_bool(std::string name, bool def, std::string doc) {
  return {std::move(name), ParamType::boolean, def, 0, 1, "", {}, std::move(doc)};
}

ParamDecl param_int(std::string name, int64_t def, int64_t min, int64_t max, std::string unit, std::string doc) {
  return {std::move(name), ParamType::integer, def, double(min), double(max), std::move(unit), {}, std::move(doc)};
}

ParamDecl param_number(std::string name, double def, double min, double max, std::string unit, std::string doc) {
  return {std::move(name), ParamType::number, def, min, max, std::move(unit), {}, std::move(doc)};
}

ParamDecl param_vec3(std::string name, std::array<double, 3> def, double min, double max, std::string unit,
                     std::string doc) {
  return {std::move(name), ParamType::vec3, def, min, max, std::move(unit), {}, std::move(doc)};
}

ParamDecl param_choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc) {
  return {std::move(name), ParamType::choice, std::move(def), 0, 0, "", std::move(choices), std::move(doc)};
}

SlotDecl slot_in(std::string name, ResourceKind kind, Usage usage, std::string doc) {
  SlotDecl s;
  s.name = std::move(name);
  s.direction = SlotDirection::input;
  s.kind = kind;
  s.usage = usage;
  s.doc = std::move(doc);
  return s;
}

SlotDecl slot_optional_in(std::string name, ResourceKind kind, Usage usage, std::string doc) {
  SlotDecl s = slot_in(std::move(name), kind, usage, std::move(doc));
  s.optional = true;
  return s;
}

SlotDecl slot_out(std::string name, ResourceKind kind, Usage usage, Format format, SizeSpec size, std::string doc) {
  SlotDecl s;
  s.name = std::move(name);
  s.direction = SlotDirection::output;
  s.kind = kind;
  s.usage = usage;
  s.format = format;
  s.size = std::move(size);
  s.doc = std::move(doc);
  return s;
}

SlotDecl slot_out_like(std::string name, std::string input_slot, Usage usage, std::string doc) {
  SlotDecl s;
  s.name = std::move(name);
  s.direction = SlotDirection::output;
  s.usage = usage;
  s.like = std::move(input_slot);
  s.doc = std::move(doc);
  return s;
}

SlotDecl slot_inout(std::string name, ResourceKind kind, Usage usage, std::string doc) {
  SlotDecl s = slot_in(std::move(name), kind, usage, std::move(doc));
  s.direction = SlotDirection::inout;
  return s;
}

SlotDecl slot_history(std::string name, std::string output_slot, std::string doc) {
  SlotDecl s;
  s.name = std::move(name);
  s.direction = SlotDirection::history;
  s.usage = Usage::sampled;
  s.history_of = std::move(output_slot);
  s.doc = std::move(doc);
  return s;
}

PassTable::PassTable(std::string name, PassKind kind, std::string doc) {
  decl.name = std::move(name);
  decl.kind = kind;
  decl.doc = std::move(doc);
}

VariantHandle PassTable::variant(std::string name, std::string doc, int32_t shader_code) {
  decl.variants.push_back({std::move(name), std::move(doc), {}, shader_code});
  return {uint16_t(decl.variants.size() - 1)};
}

template <typename T>
ParamHandle<T> PassTable::add_param(ParamDecl param) {
  decl.params.push_back(std::move(param));
  return {uint16_t(decl.params.size() - 1)};
}

ParamHandle<bool> PassTable::flag(std::string name, bool def, std::string doc) {
  return add_param<bool>(param_bool(std::move(name), def, std::move(doc)));
}

ParamHandle<int64_t> PassTable::integer(std::string name, int64_t def, int64_t min, int64_t max, std::string unit,
                                        std::string doc) {
  return add_param<int64_t>(param_int(std::move(name), def, min, max, std::move(unit), std::move(doc)));
}

ParamHandle<double> PassTable::number(std::string name, double def, double min, double max, std::string unit, std::string doc) {
  return add_param<double>(param_number(std::move(name), def, min, max, std::move(unit), std::move(doc)));
}

ParamHandle<std::array<double, 3>> PassTable::vec3(std::string name, std::array<double, 3> def, double min, double max,
                                                   std::string unit, std::string doc) {
  return add_param<std::array<double, 3>>(param_vec3(std::move(name), def, min, max, std::move(unit), std::move(doc)));
}

ParamHandle<std::string> PassTable::choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc) {
  return add_param<std::string>(param_choice(std::move(name), std::move(def), std::move(choices), std::move(doc)));
}

SlotHandle PassTable::add_slot(SlotDecl slot, const SlotOptions& options) {
  if (options.format != Format::undefined) slot.format = options.format;
  slot.persistent = options.persistent;
  slot.format_overridable = options.format_overridable;
  slot.size_overridable = options.size_overridable;
  for (const VariantHandle v : options.required_in) decl.variants.at(v.index).needs_inputs.push_back(slot.name);
  for (const VariantHandle v : options.read_in) slot.read_in.push_back(v.index);
  decl.slots.push_back(std::move(slot));
  return {uint16_t(decl.slots.size() - 1)};
}

SlotHandle PassTable::input(std::string name, ResourceKind kind, Usage usage, std::string doc, SlotOptions options) {
  return add_slot(slot_in(std::move(name), kind, usage, std::move(doc)), options);
}

SlotHandle PassTable::optional_input(std::string name, ResourceKind kind, Usage usage, std::string doc, SlotOptions options) {
  return add_slot(slot_optional_in(std::move(name), kind, usage, std::move(doc)), options);
}

SlotHandle PassTable::output(std::string name, ResourceKind kind, Usage usage, Format format, SizeSpec size, std::string doc,
                             SlotOptions options) {
  return add_slot(slot_out(std::move(name), kind, usage, format, std::move(size), std::move(doc)), options);
}

SlotHandle PassTable::output_like(std::string name, SlotHandle like, Usage usage, std::string doc) {
  const SlotDecl& source = decl.slots.at(like.index);
  SlotDecl slot = slot_out_like(std::move(name), source.name, usage, std::move(doc));
  slot.kind = source.kind;  // the kind is the source's; format and size follow the resource bound to it
  return add_slot(std::move(slot), {});
}

SlotHandle PassTable::inout(std::string name, ResourceKind kind, Usage usage, std::string doc) {
  return add_slot(slot_inout(std::move(name), kind, usage, std::move(doc)), {});
}

SlotHandle PassTable::history(std::string name, SlotHandle output, std::string doc) {
  const SlotDecl& source = decl.slots.at(output.index);
  SlotDecl slot = slot_history(std::move(name), source.name, std::move(doc));
  slot.kind = source.kind;  // last frame's version of that output: the same kind
  return add_slot(std::move(slot), {});
}

SlotHandle PassTable::internal(std::string name, ResourceKind kind, Format format, SizeSpec size, std::string doc) {
  SlotDecl slot = slot_out(std::move(name), kind, Usage::sampled, format, std::move(size), std::move(doc));
  slot.direction = SlotDirection::internal;
  return add_slot(std::move(slot), {});
}

StepHandle PassTable::step(std::string name, PassKind kind, std::vector<std::pair<SlotHandle, Usage>> uses, StepCondition when) {
  StepDecl step{std::move(name), kind, {}, nullptr, std::move(when)};
  for (const auto& [slot, usage] : uses) step.uses.push_back({slot.index, usage});
  decl.steps.push_back(std::move(step));
  return {uint16_t(decl.steps.size() - 1)};
}

StepCondition PassTable::only_in(std::vector<VariantHandle> variants) {
  StepCondition c;
  for (const VariantHandle v : variants) c.variants.push_back(v.index);
  return c;
}

StepCondition PassTable::only_in_while(VariantHandle variant, ParamHandle<int64_t> count, int64_t above) {
  StepCondition c = only_in({variant});
  c.count_param = count.index;
  c.above = above;
  return c;
}

bool StepCondition::holds(uint16_t variant, const std::vector<ParamValue>& params) const {
  if (!variants.empty() && std::find(variants.begin(), variants.end(), variant) == variants.end()) return false;
  if (count_param < 0) return true;
  const int64_t* count = std::get_if<int64_t>(&params.at(size_t(count_param)));
  return count && *count > above;
}

namespace {

// Whether step `later` runs whenever it does, for every variant and parameter value:
// `earlier` runs at least as often (its variants include later's, its count bound is no stricter).
bool runs_whenever(const StepCondition& earlier, const StepCondition& later) {
  if (earlier.always()) return true;
  if (!earlier.variants.empty()) {
    if (later.variants.empty()) return false;
    for (const uint16_t v : later.variants) {
      if (std::find(earlier.variants.begin(), earlier.variants.end(), v) == earlier.variants.end()) return false;
    }
  }
  if (earlier.count_param < 0) return true;
  return later.count_param == earlier.count_param && later.above >= earlier.above;
}

// Whether two steps never run in one pass: each runs only in variants the other does not.
bool never_together(const StepCondition& a, const StepCondition& b) {
  if (a.variants.empty() || b.variants.empty()) return false;
  for (const uint16_t v : a.variants) {
    if (std::find(b.variants.begin(), b.variants.end(), v) != b.variants.end()) return false;
  }
  return true;
}

// Whether step k makes the slot afresh beside its earlier writers: it writes without reading,
// and none of them runs with it (variants' alternative makers of one output).
bool makes_alongside(const PassDecl& decl, const std::vector<int>& writers, size_t k, Usage usage) {
  if (!usage_writes(usage) || usage_reads(usage)) return false;
  for (const int w : writers) {
    if (!never_together(decl.steps[size_t(w)].when, decl.steps[k].when)) return false;
  }
  return true;
}

void check_step_conditions(const PassDecl& decl) {
  if (!decl.steps.empty() && !decl.steps.front().when.always()) {
    throw std::logic_error("pass type " + decl.name + ": its first step \"" + decl.steps.front().name + "\" must always run");
  }
  std::vector<std::vector<int>> makers(decl.slots.size());  // the steps that write each slot first (alternatives by variant)
  for (size_t k = 0; k < decl.steps.size(); ++k) {
    for (const auto& [slot, usage] : decl.steps[k].uses) {
      const SlotDirection outer = decl.slots.at(slot).direction;
      if (outer == SlotDirection::input || outer == SlotDirection::history || outer == SlotDirection::inout) continue;
      std::vector<int>& made_by = makers[slot];
      if (made_by.empty() || makes_alongside(decl, made_by, k, usage)) {
        if (usage_writes(usage)) made_by.push_back(int(k));
        continue;
      }
      const bool covered = std::any_of(made_by.begin(), made_by.end(),
                                       [&](int m) { return runs_whenever(decl.steps[size_t(m)].when, decl.steps[k].when); });
      if (!covered) {
        throw std::logic_error("pass type " + decl.name + ": step \"" + decl.steps[k].name + "\" uses slot \"" + decl.slots[slot].name +
                               "\" where step \"" + decl.steps[size_t(made_by.front())].name + "\", which makes it, does not run");
      }
    }
  }
}

}  // namespace

void finish_steps(PassDecl& decl) {
  check_step_conditions(decl);
  std::vector<std::vector<int>> writers(decl.slots.size());  // the earlier steps that write each slot
  for (size_t k = 0; k < decl.steps.size(); ++k) {
    StepDecl& step = decl.steps[k];
    PassDecl d = decl;
    d.steps.clear();
    d.kind = step.kind;
    for (const auto& [slot, usage] : step.uses) {
      SlotDecl& s = d.slots.at(slot);
      const SlotDirection outer = decl.slots[slot].direction;
      s.usage = usage;
      if (outer == SlotDirection::input || outer == SlotDirection::history) continue;
      if (!usage_writes(usage)) {
        s.direction = SlotDirection::input;
        s.optional = false;
        s.format = Format::undefined;  // the resource's own (checked where it is made)
      } else if (outer == SlotDirection::inout || (!writers[slot].empty() && !makes_alongside(decl, writers[slot], k, usage))) {
        s.direction = SlotDirection::inout;
        s.format = Format::undefined;
      } else {
        s.direction = SlotDirection::output;
      }
      if (usage_writes(usage)) writers[slot].push_back(int(k));
    }
    step.decl = std::make_shared<const PassDecl>(std::move(d));
  }
}

std::string_view pass_kind_name(PassKind kind) {
  switch (kind) {
    case PassKind::compute: return "compute";
    case PassKind::graphics: return "graphics";
    case PassKind::transfer: return "transfer";
  }
  return "?";
}

std::string_view param_type_name(ParamType type) {
  switch (type) {
    case ParamType::boolean: return "boolean";
    case ParamType::integer: return "integer";
    case ParamType::number: return "number";
    case ParamType::vec3: return "vec3";
    case ParamType::choice: return "choice";
  }
  return "?";
}

std::string param_value_text(const ParamValue& value) {
  struct Visitor {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(int64_t i) const { return std::to_string(i); }
    std::string operator()(double d) const { return number_text(d); }
    std::string operator()(const std::array<double, 3>& v) const {
      return "[" + number_text(v[0]) + ", " + number_text(v[1]) + ", " + number_text(v[2]) + "]";
    }
    std::string operator()(const std::string& s) const { return "\"" + s + "\""; }
  };
  return std::visit(Visitor{}, value);
}

}  // namespace volgraph
