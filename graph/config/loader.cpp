// Config files → Config → Graph. Each file is checked strictly on its own (unknown
// keys, types, ranges), includes first; then the passes are wired, which is where
// pass types, variants, parameters and slots are checked against the registry.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "graph/config/config.h"
#include "graph/config/json_reader.h"
#include "graph/config/scene_reader.h"
#include "graph/plan.h"

namespace volgraph {
namespace {

using config::Json;
using config::Node;
using config::Source;
using config::valid_name;

constexpr uint32_t kMaxTexture2D = 16384;
constexpr uint32_t kMaxTexture3D = 2048;
constexpr int kMaxIncludeDepth = 16;

const Where kCommandLine{"<command line>", "", 0};

bool integer_format(Format f) { return f == Format::r32_uint; }

// Raw JSON into a ParamValue; the parameter's type is checked once the pass type is known.
std::optional<ParamValue> raw_param(const Node& n) {
  const Json& j = n.json();
  if (j.is_boolean()) return j.get<bool>();
  if (j.is_number_integer()) return j.get<int64_t>();
  if (j.is_number_float()) return j.get<double>();
  if (j.is_string()) return j.get<std::string>();
  if (j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number()) {
    return std::array<double, 3>{j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
  }
  n.error("expected a boolean, number, string or array of 3 numbers, got " + config::describe(j));
  return std::nullopt;
}

std::optional<SizeSpec> read_size(const Node& n, ResourceKind kind) {
  const Json& j = n.json();
  if (kind == ResourceKind::buffer) {
    const auto bytes = n.integer(4, int64_t{1} << 31);
    return bytes ? std::optional(SizeSpec::bytes(uint64_t(*bytes))) : std::nullopt;
  }
  if (j.is_object()) {  // {"scale": [sx, sy], "depth": d}
    if (!n.object({"scale", "depth"})) return std::nullopt;
    SizeSpec s = SizeSpec::of_output(1, 1, 1);
    if (auto sc = n.member("scale")) {
      if (!sc->array() || sc->size() != 2) {
        sc->error("expected [scale_x, scale_y], got " + config::describe(sc->json()));
        return std::nullopt;
      }
      const auto x = sc->element(0).number(1.0 / 64, 4), y = sc->element(1).number(1.0 / 64, 4);
      if (!x || !y) return std::nullopt;
      s.scale_x = float(*x);
      s.scale_y = float(*y);
    }
    if (auto d = n.member("depth")) {
      const auto depth = d->integer(1, kMaxTexture3D);
      if (!depth) return std::nullopt;
      s.absolute.depth = uint32_t(*depth);
    }
    return s;
  }
  const size_t dims = kind == ResourceKind::texture3d ? 3 : 2;
  if (!j.is_array() || j.size() != dims) {
    n.error("expected " + std::string(dims == 3 ? "[width, height, depth]" : "[width, height]") +
            " or {\"scale\": [sx, sy]}, got " + config::describe(j));
    return std::nullopt;
  }
  const uint32_t limit = dims == 3 ? kMaxTexture3D : kMaxTexture2D;
  uint32_t e[3] = {1, 1, 1};
  for (size_t i = 0; i < dims; ++i) {
    const auto v = n.element(i).integer(1, limit);
    if (!v) return std::nullopt;
    e[i] = uint32_t(*v);
  }
  return SizeSpec::fixed(e[0], e[1], e[2]);
}

void set_param(PassNode& p, ParamSetting s) {
  std::erase_if(p.params, [&](const ParamSetting& x) { return x.name == s.name; });
  p.params.push_back(std::move(s));
}

// Output size overrides by (pass, slot), parsed once the slot's kind is known.
using SizeNodes = std::map<std::pair<std::string, std::string>, Node>;

class Loader {
 public:
  explicit Loader(Config& config) : config_(config) {}

  void load_file(const std::string& path, const std::string* text, int depth, const Where& from) {
    if (depth > kMaxIncludeDepth) {
      diags_.error(from, "includes nest deeper than " + std::to_string(kMaxIncludeDepth) + " files (an include cycle?)");
      return;
    }
    std::error_code ec;
    std::string canonical = std::filesystem::weakly_canonical(path, ec).string();
    if (ec) canonical = path;
    if (std::find(stack_.begin(), stack_.end(), canonical) != stack_.end()) {
      diags_.error(from, "include cycle: \"" + path + "\" includes itself");
      return;
    }
    std::string contents;
    if (text) {
      contents = *text;
    } else if (const std::string problem = config::read_text_file(path, contents); !problem.empty()) {
      diags_.error(from.file.empty() ? Where{path, "", 0} : from, "cannot read \"" + path + "\": " + problem);
      return;
    }
    config_.files.push_back(path);
    sources_.push_back(std::make_unique<Source>());
    Source& src = *sources_.back();
    src.file = path;
    src.dir = std::filesystem::path(path).parent_path().string();
    std::optional<Json> json = config::parse_json_document(path, contents, diags_);
    if (!json) return;
    jsons_.push_back(std::make_unique<Json>(std::move(*json)));
    src.lines = index_json_lines(contents);
    stack_.push_back(canonical);
    read_document(Node(src, *jsons_.back(), "", diags_), depth);
    stack_.pop_back();
  }

  Diagnostics& diagnostics() { return diags_; }

 private:
  void read_document(const Node& doc, int depth) {
    if (!doc.object({"description", "include", "output", "scene", "graph"})) return;
    if (auto inc = doc.member("include")) read_includes(*inc, depth);
    if (auto d = doc.member("description")) {
      if (auto text = d->string()) config_.description = *text;
    }
    if (auto out = doc.member("output")) read_output(*out);
    if (auto scene = doc.member("scene")) config::read_scene(*scene, config_.scene);
    if (auto graph = doc.member("graph")) read_graph(*graph);
  }

  void read_includes(const Node& inc, int depth) {
    auto one = [&](const Node& n) {
      const auto rel = n.string();
      if (!rel) return;
      const std::string path = (std::filesystem::path(n.source().dir) / *rel).lexically_normal().string();
      load_file(path, nullptr, depth + 1, n.where());
    };
    if (inc.json().is_array()) {
      for (size_t i = 0; i < inc.size(); ++i) one(inc.element(i));
    } else {
      one(inc);
    }
  }

  void read_output(const Node& out) {
    if (!out.object({"size"})) return;
    if (auto size = out.member("size")) {
      if (auto s = read_size(*size, ResourceKind::texture2d)) config_.output_size = s->absolute;
    }
  }

  void read_graph(const Node& graph) {
    if (!graph.object({"passes", "outputs"})) return;
    if (auto passes = graph.member("passes"); passes && passes->array()) {
      std::vector<std::string> seen_here;
      for (size_t i = 0; i < passes->size(); ++i) read_pass(passes->element(i), seen_here);
    }
    if (auto outputs = graph.member("outputs"); outputs && outputs->array()) {
      config_.outputs.clear();
      for (size_t i = 0; i < outputs->size(); ++i) {
        const Node o = outputs->element(i);
        if (auto s = o.string()) config_.outputs.push_back({*s, o.where()});
      }
    }
  }

  // A pass with "type" defines (or replaces) a pass; without, it amends one an
  // included file defined: its variant, parameters, inputs and outputs.
  void read_pass(const Node& n, std::vector<std::string>& seen_here) {
    if (!n.object({"name", "type", "variant", "params", "inputs", "outputs"})) return;
    const auto name_node = n.member("name");
    if (!name_node) return n.error("missing key \"name\"");
    const auto name = name_node->string();
    if (!name) return;
    if (!valid_name(*name)) {
      return name_node->error("pass name \"" + *name + "\" must be letters, digits and _ (not starting with a digit)");
    }
    if (std::find(seen_here.begin(), seen_here.end(), *name) != seen_here.end()) {
      return name_node->error("pass \"" + *name + "\" is defined twice in this file");
    }
    seen_here.push_back(*name);
    auto it = std::find_if(config_.passes.begin(), config_.passes.end(), [&](const PassNode& p) { return p.name == *name; });
    const auto type_node = n.member("type");
    if (!type_node && it == config_.passes.end()) {
      return n.error("pass \"" + *name + "\" has no \"type\" (only a pass an included file defines may omit it)");
    }
    if (type_node || it == config_.passes.end()) {
      std::erase_if(sizes_, [&](const auto& entry) { return entry.first.first == *name; });
      PassNode fresh;
      fresh.name = *name;
      if (it == config_.passes.end()) {
        config_.passes.push_back(std::move(fresh));
        it = config_.passes.end() - 1;
      } else {
        *it = std::move(fresh);
      }
    }
    PassNode& p = *it;
    p.where = n.where();
    if (type_node) {
      if (auto t = type_node->string()) p.type = *t;
      p.type_where = type_node->where();
    }
    if (auto v = n.member("variant")) {
      if (auto text = v->string()) p.variant = *text;
      p.variant_where = v->where();
    }
    if (auto params = n.member("params"); params && params->object_any_keys()) {
      for (const auto& [key, value] : params->json().items()) {
        (void)value;
        const Node pn = params->child(key);
        if (auto raw = raw_param(pn)) set_param(p, {key, *raw, pn.where()});
      }
    }
    if (auto inputs = n.member("inputs"); inputs && inputs->object_any_keys()) {
      for (const auto& item : inputs->json().items()) {
        const std::string slot = item.key();
        const Node in = inputs->child(slot);
        // null unwires what an included file wired (an optional input a variant leaves unread).
        if (in.json().is_null()) {
          std::erase_if(p.inputs, [&](const InputWiring& w) { return w.slot == slot; });
          continue;
        }
        const auto source = in.string();
        if (!source) continue;
        std::erase_if(p.inputs, [&](const InputWiring& w) { return w.slot == slot; });
        p.inputs.push_back({slot, *source, in.where()});
      }
    }
    if (auto outputs = n.member("outputs"); outputs && outputs->object_any_keys()) {
      for (const auto& [slot, value] : outputs->json().items()) {
        (void)value;
        read_output_override(outputs->child(slot), slot, p);
      }
    }
  }

  void read_output_override(const Node& n, const std::string& slot, PassNode& p) {
    if (!n.object({"format", "size"})) return;
    OutputOverride o;
    o.slot = slot;
    o.where = n.where();
    if (auto f = n.member("format")) {
      if (auto text = f->string()) {
        if (auto format = format_from_name(*text)) {
          o.format = format;
        } else {
          std::vector<std::string> names;
          for (int i = 1; i <= int(Format::d32_float); ++i) names.emplace_back(format_info(Format(i)).name);
          f->error("unknown format \"" + *text + "\"" + did_you_mean(*text, names) + "; expected " + one_of(names));
        }
      }
    }
    if (auto s = n.member("size")) {
      // The slot's kind is known only once the pass type is; keep the JSON for later.
      sizes_.insert_or_assign({p.name, slot}, *s);
    }
    std::erase_if(p.outputs, [&](const OutputOverride& x) { return x.slot == slot; });
    p.outputs.push_back(o);
  }

 public:
  const SizeNodes& sizes() const { return sizes_; }

  // --graph FILE: the passes and outputs read so far dropped, FILE's read in their
  // place (the config's scene, size and description kept).
  void replace_graph(const std::string& path, const Where& from) {
    config_.passes.clear();
    config_.outputs.clear();
    sizes_.clear();
    const std::string description = config_.description;
    load_file(path, nullptr, 0, from);
    config_.description = description;
  }

 private:
  SizeNodes sizes_;
  Config& config_;
  Diagnostics diags_;
  std::vector<std::string> stack_;
  std::vector<std::unique_ptr<Source>> sources_;
  std::vector<std::unique_ptr<Json>> jsons_;
};

std::vector<std::string> names_of(const auto& items) {
  std::vector<std::string> out;
  for (const auto& x : items) out.push_back(x.name);
  return out;
}

// Whether variant `variant` reads optional input `slot` (SlotOptions::read_in; none named: every variant).
bool read_in_variant(const SlotDecl& slot, uint16_t variant) {
  return slot.read_in.empty() || std::find(slot.read_in.begin(), slot.read_in.end(), variant) != slot.read_in.end();
}

// "\"a\"" or "\"a\" or \"b\"": the variants of `decl` at `indices`, quoted.
std::string variant_names(const PassDecl& decl, const std::vector<uint16_t>& indices) {
  std::string text;
  for (size_t i = 0; i < indices.size(); ++i) text += (i ? " or \"" : "\"") + decl.variants.at(indices[i]).name + "\"";
  return text;
}

// A parameter value of the declared type and range, or a diagnostic.
std::optional<ParamValue> checked_param(const ParamDecl& decl, const ParamValue& raw, const Where& where,
                                        Diagnostics& diags) {
  const std::string expected = [&] {
    switch (decl.type) {
      case ParamType::boolean: return std::string("true or false");
      case ParamType::integer: return "an integer in " + config::range_text(decl.min, decl.max);
      case ParamType::number: return "a number in " + config::range_text(decl.min, decl.max);
      case ParamType::vec3: return "an array of 3 numbers in " + config::range_text(decl.min, decl.max);
      case ParamType::choice: return one_of(decl.choices);
    }
    return std::string();
  }();
  auto fail = [&]() -> std::optional<ParamValue> {
    diags.error(where, "parameter \"" + decl.name + "\" expects " + expected + ", got " + param_value_text(raw));
    return std::nullopt;
  };
  auto in_range = [&](double v) { return std::isfinite(v) && v >= decl.min && v <= decl.max; };
  switch (decl.type) {
    case ParamType::boolean:
      if (std::holds_alternative<bool>(raw)) return raw;
      return fail();
    case ParamType::integer: {
      double v;
      if (auto i = std::get_if<int64_t>(&raw)) v = double(*i);
      else if (auto d = std::get_if<double>(&raw); d && std::floor(*d) == *d) v = *d;
      else return fail();
      if (!in_range(v)) return fail();
      return int64_t(v);
    }
    case ParamType::number: {
      double v;
      if (auto i = std::get_if<int64_t>(&raw)) v = double(*i);
      else if (auto d = std::get_if<double>(&raw)) v = *d;
      else return fail();
      if (!in_range(v)) return fail();
      return v;
    }
    case ParamType::vec3: {
      const auto* v = std::get_if<std::array<double, 3>>(&raw);
      if (!v || !in_range((*v)[0]) || !in_range((*v)[1]) || !in_range((*v)[2])) return fail();
      return raw;
    }
    case ParamType::choice: {
      const auto* text = std::get_if<std::string>(&raw);
      if (!text) return fail();
      if (std::find(decl.choices.begin(), decl.choices.end(), *text) != decl.choices.end()) return raw;
      diags.error(where, "parameter \"" + decl.name + "\" has no choice \"" + *text + "\"" +
                             did_you_mean(*text, decl.choices) + "; expected " + expected);
      return std::nullopt;
    }
  }
  return fail();
}

struct SlotRef {
  uint32_t pass;
  int slot;
};

// Wires a checked config into a Graph.
class Wiring {
 public:
  Wiring(const Config& config, const PassRegistry& registry, const SizeNodes& sizes, Diagnostics& diags)
      : config_(config), registry_(registry), sizes_(sizes), diags_(diags) {}

  LoadedConfig run() {
    const size_t n = config_.passes.size();
    decls_.assign(n, nullptr);
    variants_.assign(n, 0);
    params_.resize(n);
    overrides_.resize(n);
    inputs_.resize(n);
    for (uint32_t p = 0; p < n; ++p) index_[config_.passes[p].name] = p;
    for (uint32_t p = 0; p < n; ++p) check_type(p);
    diags_.throw_if_any();
    for (uint32_t p = 0; p < n; ++p) check_params_and_outputs(p);
    for (uint32_t p = 0; p < n; ++p) check_inputs(p);
    for (uint32_t p = 0; p < n; ++p) check_against_scene(p);
    check_outputs_named();
    diags_.throw_if_any();
    const std::vector<uint32_t> order = wiring_order();
    diags_.throw_if_any();
    return build(order);
  }

 private:
  void check_type(uint32_t p) {
    const PassNode& node = config_.passes[p];
    decls_[p] = registry_.find(node.type);
    if (!decls_[p]) {
      diags_.error(node.type_where, "unknown pass type \"" + node.type + "\"" + did_you_mean(node.type, registry_.names()) +
                                        "; expected " + one_of(registry_.names()));
      return;
    }
    if (node.variant.empty()) return;
    const int v = decls_[p]->variant_index(node.variant);
    if (v < 0) {
      const auto names = names_of(decls_[p]->variants);
      diags_.error(node.variant_where, "pass type \"" + node.type + "\" has no variant \"" + node.variant + "\"" +
                                           did_you_mean(node.variant, names) + "; expected " + one_of(names));
      return;
    }
    variants_[p] = uint16_t(v);
  }

  void check_params_and_outputs(uint32_t p) {
    const PassNode& node = config_.passes[p];
    const PassDecl& decl = *decls_[p];
    for (const ParamDecl& pd : decl.params) params_[p].push_back(pd.default_value);
    for (const ParamSetting& s : node.params) {
      const int i = decl.param_index(s.name);
      if (i < 0) {
        const auto names = names_of(decl.params);
        diags_.error(s.where, "pass type \"" + decl.name + "\" has no parameter \"" + s.name + "\"" +
                                  did_you_mean(s.name, names) +
                                  (names.empty() ? "; it takes none" : "; expected " + one_of(names)));
        continue;
      }
      if (auto v = checked_param(decl.params[size_t(i)], s.value, s.where, diags_)) params_[p][size_t(i)] = *v;
    }
    overrides_[p].assign(decl.slots.size(), nullptr);
    for (const OutputOverride& o : node.outputs) {
      const int i = find_slot(decl, o.slot, o.where, "output");
      if (i < 0) continue;
      const SlotDecl& slot = decl.slots[size_t(i)];
      if (slot.direction != SlotDirection::output) {
        const char* what = slot.direction == SlotDirection::internal ? "internal to the pass" : "an input";
        diags_.error(o.where, "slot \"" + o.slot + "\" of \"" + decl.name + "\" is " + what + "; only outputs take a format or size");
        continue;
      }
      overrides_[p][size_t(i)] = &o;
      check_format_override(decl, slot, o);
      check_size_override(node, slot);
    }
  }

  // A pass's own checks of its parameters against the scene, when the pass will run
  // (its scene needs hold); a problem points at the parameter when it names one.
  void check_against_scene(uint32_t p) {
    const PassDecl& decl = *decls_[p];
    if (!decl.check_scene || !needs_hold(decl.needs, decl.needs_any, config_.scene.features())) return;
    const PassNode& node = config_.passes[p];
    for (const ParamProblem& problem : decl.check_scene(decl, config_.scene, params_[p])) {
      if (problem.where) {
        if (problem.warning) diags_.warning(*problem.where, problem.message);
        else diags_.error(*problem.where, problem.message);
        continue;
      }
      Where where = node.where;
      for (const ParamSetting& s : node.params) {
        if (s.name == problem.param) where = s.where;
      }
      if (problem.warning) diags_.warning(where, "pass \"" + node.name + "\": " + problem.message);
      else diags_.error(where, "pass \"" + node.name + "\": " + problem.message);
    }
  }

  void check_format_override(const PassDecl& decl, const SlotDecl& slot, const OutputOverride& o) {
    if (!o.format) return;
    if (!slot.format_overridable) {
      diags_.error(o.where, "the format of \"" + decl.name + "." + slot.name + "\" is fixed (" +
                                std::string(format_info(slot.format).name) + ")");
      return;
    }
    const FormatInfo& f = format_info(*o.format);
    if (integer_format(*o.format) != integer_format(slot.format)) {
      diags_.error(o.where, "slot \"" + slot.name + "\" of \"" + decl.name + "\" holds " +
                                (integer_format(slot.format) ? "integers" : "floating-point or normalised values") + ", " +
                                std::string(f.name) + " does not; expected a format like " + std::string(format_info(slot.format).name));
    } else if (f.is_depth != format_info(slot.format).is_depth) {
      diags_.error(o.where, "slot \"" + slot.name + "\" needs a " + (f.is_depth ? "colour" : "depth") + " format, got " +
                                std::string(f.name));
    } else if ((slot.usage == Usage::storage_write || slot.usage == Usage::storage_read_write) && !f.storage_capable) {
      diags_.error(o.where, "slot \"" + slot.name + "\" is written as storage; " + std::string(f.name) +
                                " is not a storage format on both backends");
    }
  }

  void check_size_override(const PassNode& node, const SlotDecl& slot) {
    const auto it = sizes_.find({node.name, slot.name});
    if (it == sizes_.end()) return;
    if (!slot.size_overridable) {
      it->second.error("the size of \"" + node.name + "." + slot.name + "\" is fixed by its pass");
      return;
    }
    if (auto s = read_size(it->second, slot.kind)) sizes_resolved_[{node.name, slot.name}] = *s;
  }

  int find_slot(const PassDecl& decl, const std::string& slot, const Where& where, const char* what) {
    const int i = decl.slot_index(slot);
    if (i >= 0) return i;
    const auto names = names_of(decl.slots);
    diags_.error(where, "pass type \"" + decl.name + "\" has no " + what + " slot \"" + slot + "\"" +
                            did_you_mean(slot, names) + "; expected " + one_of(names));
    return -1;
  }

  // "pass.slot" → the pass and its output or inout slot.
  std::optional<SlotRef> resolve_source(const std::string& source, const Where& where) {
    const size_t dot = source.find('.');
    if (dot == std::string::npos) {
      diags_.error(where, "expected \"pass.slot\", got \"" + source + "\"");
      return std::nullopt;
    }
    const std::string pass = source.substr(0, dot), slot = source.substr(dot + 1);
    const auto it = index_.find(pass);
    if (it == index_.end()) {
      std::vector<std::string> names;
      for (const auto& [name, i] : index_) names.push_back(name);
      diags_.error(where, "no pass named \"" + pass + "\"" + did_you_mean(pass, names));
      return std::nullopt;
    }
    const PassDecl* decl = decls_[it->second];
    if (!decl) return std::nullopt;
    std::vector<std::string> outputs;
    auto is_source = [](const SlotDecl& s) { return s.direction == SlotDirection::output || s.direction == SlotDirection::inout; };
    for (const SlotDecl& s : decl->slots) {
      if (is_source(s)) outputs.push_back(s.name);
    }
    const int i = decl->slot_index(slot);
    if (i < 0 || !is_source(decl->slots[size_t(i)])) {
      diags_.error(where, "pass \"" + pass + "\" (" + decl->name + ") has no output \"" + slot + "\"" +
                              did_you_mean(slot, outputs) + "; expected " + one_of(outputs));
      return std::nullopt;
    }
    return SlotRef{it->second, i};
  }

  void check_inputs(uint32_t p) {
    const PassNode& node = config_.passes[p];
    const PassDecl& decl = *decls_[p];
    inputs_[p].assign(decl.slots.size(), std::nullopt);
    wiring_where_.resize(config_.passes.size());
    wiring_where_[p].assign(decl.slots.size(), node.where);
    for (const InputWiring& w : node.inputs) {
      const int i = find_slot(decl, w.slot, w.where, "input");
      if (i < 0) continue;
      if (decl.slots[size_t(i)].direction == SlotDirection::internal) {
        diags_.error(w.where, "slot \"" + w.slot + "\" of \"" + decl.name + "\" is internal to the pass; it cannot be wired");
        continue;
      }
      if (decl.slots[size_t(i)].direction == SlotDirection::output) {
        diags_.error(w.where, "slot \"" + w.slot + "\" of \"" + decl.name + "\" is an output; it cannot be wired to an input");
        continue;
      }
      if (decl.slots[size_t(i)].direction == SlotDirection::history) {
        diags_.error(w.where, "slot \"" + w.slot + "\" of \"" + decl.name + "\" is the previous frame of its output \"" +
                                  decl.slots[size_t(i)].history_of + "\"; the graph binds it, it cannot be wired");
        continue;
      }
      if (!read_in_variant(decl.slots[size_t(i)], variants_[p])) {
        diags_.error(w.where, "input \"" + w.slot + "\" of \"" + decl.name + "\" is read only in variant " +
                                  variant_names(decl, decl.slots[size_t(i)].read_in) + "; variant \"" +
                                  decl.variants[variants_[p]].name + "\" would ignore it (unwire it or choose that variant)");
        continue;
      }
      inputs_[p][size_t(i)] = resolve_source(w.source, w.where);
      wiring_where_[p][size_t(i)] = w.where;
    }
    for (size_t i = 0; i < decl.slots.size(); ++i) {
      const SlotDecl& s = decl.slots[i];
      if (s.direction == SlotDirection::output || s.direction == SlotDirection::history || s.direction == SlotDirection::internal ||
          inputs_[p][i]) {
        continue;
      }
      if (std::any_of(node.inputs.begin(), node.inputs.end(), [&](const InputWiring& w) { return w.slot == s.name; })) continue;
      const VariantDecl& variant = decl.variants[variants_[p]];
      const bool needed = std::find(variant.needs_inputs.begin(), variant.needs_inputs.end(), s.name) != variant.needs_inputs.end();
      if (s.optional && !needed) continue;
      const std::string why = s.optional ? " (variant \"" + variant.name + "\" needs it)" : "";
      diags_.error(node.where, "pass \"" + node.name + "\" (" + decl.name + "): input \"" + s.name + "\" (" +
                                   std::string(kind_name(s.kind)) + ") is not wired" + why);
    }
  }

  void check_outputs_named() {
    if (config_.outputs.empty()) {
      diags_.error({config_.file, "/graph/outputs", 0}, "the graph has no outputs; expected \"outputs\": [\"pass.slot\", …]");
    }
    for (const GraphOutput& o : config_.outputs) outputs_.push_back(resolve_source(o.source, o.where));
    // The first output is the frame (render -o writes it): an image. Later ones may be
    // anything a caller reads back.
    if (!outputs_.empty() && outputs_[0] && decls_[outputs_[0]->pass]->slots[size_t(outputs_[0]->slot)].kind == ResourceKind::buffer) {
      diags_.error(config_.outputs[0].where, "\"" + config_.outputs[0].source +
                                                 "\" is a buffer; the first graph output is the frame, an image (--dump "
                                                 "PASS.SLOT=FILE.bin writes a buffer)");
    }
  }

  // Passes in an order where every source comes before its readers; reports cycles.
  std::vector<uint32_t> wiring_order() {
    const size_t n = config_.passes.size();
    std::vector<uint8_t> state(n, 0);
    std::vector<uint32_t> order, path;
    std::function<bool(uint32_t)> visit = [&](uint32_t p) -> bool {
      if (state[p] == 2) return true;
      if (state[p] == 1) {
        std::string text;
        auto start = std::find(path.begin(), path.end(), p);
        for (auto it = start; it != path.end(); ++it) text += config_.passes[*it].name + " → ";
        diags_.error(config_.passes[p].where, "the graph has a cycle: " + text + config_.passes[p].name);
        return false;
      }
      state[p] = 1;
      path.push_back(p);
      for (const auto& src : inputs_[p]) {
        if (src && !visit(src->pass)) return false;
      }
      path.pop_back();
      state[p] = 2;
      order.push_back(p);
      return true;
    };
    for (uint32_t p = 0; p < n; ++p) {
      if (!visit(p)) break;
    }
    return order;
  }

  LoadedConfig build(const std::vector<uint32_t>& order) {
    LoadedConfig out;
    out.config = config_;
    out.warnings = diags_.warnings();
    GraphBuilder b(config_.output_size, config_.scene.features());
    for (uint32_t p = 0; p < config_.passes.size(); ++p) add_pass(b, p, 0);
    steps_.assign(config_.passes.size(), {});
    for (uint32_t p = 0; p < config_.passes.size(); ++p) {
      steps_[p].push_back(p);
      for (uint16_t k = 1; k < decls_[p]->steps.size(); ++k) {
        const bool runs = decls_[p]->steps[k].when.holds(variants_[p], params_[p]);
        steps_[p].push_back(runs ? add_pass(b, p, k) : kNone);
      }
    }
    std::vector<std::vector<ResourceVersion>> made(config_.passes.size());
    for (uint32_t p : order) {
      const PassDecl& decl = *decls_[p];
      made[p].resize(decl.slots.size());
      if (!decl.steps.empty()) {
        bind_steps(b, p, made);
        continue;
      }
      // Inputs first (an output may be shaped like one), then outputs, then the history
      // slots that follow them.
      for (const int stage : {0, 1, 2}) {
        for (uint16_t i = 0; i < decl.slots.size(); ++i) {
          if (binding_stage(decl.slots[i].direction) != stage) continue;
          try {
            made[p][i] = bind_slot(b, p, i, made);
          } catch (const GraphError& e) {
            diags_.error(wiring_where_[p][i], "pass \"" + config_.passes[p].name + "\": " + e.what());
          }
        }
      }
    }
    for (size_t o = 0; o < outputs_.size(); ++o) {
      try {
        b.mark_output(made[outputs_[o]->pass][size_t(outputs_[o]->slot)]);
      } catch (const GraphError& e) {
        diags_.error(config_.outputs[o].where, e.what());
      }
    }
    diags_.throw_if_any();
    out.graph = b.finish();
    for (uint32_t p = 0; p < config_.passes.size(); ++p) {
      for (const uint32_t step : steps_[p]) {
        if (step != kNone) out.graph.passes[step].params = params_[p];
      }
    }
    out.params = params_;
    return out;
  }

  // Config pass p as a graph pass: itself, or its step `step` ("name/step", the step's
  // decl) when its type has steps.
  uint32_t add_pass(GraphBuilder& b, uint32_t p, uint16_t step) {
    const PassDecl& decl = *decls_[p];
    if (decl.steps.empty()) return b.add_pass(config_.passes[p].name, decl, variants_[p]);
    const StepDecl& s = decl.steps[step];
    const uint32_t g = b.add_pass(config_.passes[p].name + "/" + s.name, *s.decl, variants_[p]);
    b.graph().passes[g].group = p;
    b.graph().passes[g].step = step;
    return g;
  }

  // A pass made of steps: each step binds the slots it uses, in step order — the pass's
  // inputs as wired, its outputs and internal slots made by the first step that writes
  // them (named "pass.slot", as a pass's own outputs are) and modified by later ones.
  // Steps whose condition does not hold were not added (kNone): they bind nothing.
  void bind_steps(GraphBuilder& b, uint32_t p, std::vector<std::vector<ResourceVersion>>& made) {
    const PassDecl& decl = *decls_[p];
    std::vector<uint8_t> exists(decl.slots.size(), 0);
    for (uint16_t k = 0; k < decl.steps.size(); ++k) {
      const uint32_t g = steps_[p][k];
      if (g == kNone) continue;
      for (const auto& [slot, usage] : decl.steps[k].uses) {
        const SlotDecl& s = decl.steps[k].decl->slots[slot];
        const std::optional<SlotRef>& wired = inputs_[p][slot];
        try {
          if (s.direction == SlotDirection::output) {
            SizeRule rule;
            ResourceDesc d = output_desc(p, decl.slots[slot], &rule);
            d.name = config_.passes[p].name + "." + s.name;
            made[p][slot] = b.create(g, slot, d);
            b.graph().resources[made[p][slot].resource].size_rule = rule;
            exists[slot] = 1;
          } else if (decl.slots[slot].direction == SlotDirection::input) {
            if (wired) b.read(g, slot, made[wired->pass][size_t(wired->slot)]);
          } else if (s.direction == SlotDirection::inout) {
            made[p][slot] = b.modify(g, slot, exists[slot] ? made[p][slot] : made[wired->pass][size_t(wired->slot)]);
            exists[slot] = 1;
          } else {
            b.read(g, slot, made[p][slot]);
          }
        } catch (const GraphError& e) {
          diags_.error(wiring_where_[p][slot], "pass \"" + config_.passes[p].name + "\": " + e.what());
        }
      }
    }
  }

  static int binding_stage(SlotDirection direction) {
    return direction == SlotDirection::output ? 1 : direction == SlotDirection::history ? 2 : 0;
  }

  ResourceVersion bind_slot(GraphBuilder& b, uint32_t p, uint16_t i, const std::vector<std::vector<ResourceVersion>>& made) {
    const PassDecl& decl = *decls_[p];
    const SlotDecl& slot = decl.slots[i];
    if (slot.direction == SlotDirection::history) {
      const int followed = decl.slot_index(slot.history_of);
      if (followed < 0) throw GraphError(p, i, "history slot \"" + slot.name + "\" follows no output \"" + slot.history_of + "\"");
      return b.read_history(p, i, made[p][size_t(followed)]);
    }
    if (slot.direction == SlotDirection::output && !slot.like.empty()) {
      const ResourceVersion v = b.create(p, i, like_desc(b, p, slot, made));
      const SlotRef& source = *inputs_[p][size_t(decls_[p]->slot_index(slot.like))];  // like_desc checked it is wired
      b.graph().resources[v.resource].size_rule.like = made[source.pass][size_t(source.slot)].resource;
      return v;
    }
    if (slot.direction == SlotDirection::output) {
      SizeRule rule;
      const ResourceVersion v = b.create(p, i, output_desc(p, slot, &rule));
      b.graph().resources[v.resource].size_rule = rule;
      return v;
    }
    const auto& src = inputs_[p][i];
    if (!src) return {};
    const ResourceVersion v = made[src->pass][size_t(src->slot)];
    if (slot.direction == SlotDirection::inout) return b.modify(p, i, v);
    b.read(p, i, v);
    return {};
  }

  // An output shaped like the resource wired to one of the pass's inputs (a copy).
  ResourceDesc like_desc(GraphBuilder& b, uint32_t p, const SlotDecl& slot,
                         const std::vector<std::vector<ResourceVersion>>& made) {
    const auto& src = inputs_[p][size_t(decls_[p]->slot_index(slot.like))];
    if (!src) throw GraphError(p, decls_[p]->slot_index(slot.name), "output \"" + slot.name + "\" copies input \"" + slot.like + "\", which is not wired");
    ResourceDesc d = b.graph().resources[made[src->pass][size_t(src->slot)].resource].desc;
    d.name.clear();
    d.persistent = slot.persistent;
    return d;
  }

  // The value of a size's divisor parameter: an integer, or the divisor of a choice.
  static int64_t divisor_of(const SizeSpec& size, const ParamValue& value) {
    if (const int64_t* n = std::get_if<int64_t>(&value)) return *n;
    for (const auto& [choice, divisor] : size.divisor_choices) {
      if (choice == std::get<std::string>(value)) return divisor;
    }
    return 1;
  }

  ResourceDesc output_desc(uint32_t p, const SlotDecl& slot, SizeRule* rule) {
    const PassDecl& decl = *decls_[p];
    int64_t side = 0, divisor = 1, depth = 1, height = 0, mips = 1;
    const std::vector<ParamValue>& values = params_[p];
    if (slot.size.mip_param) mips = std::get<int64_t>(values[*slot.size.mip_param]);
    if (slot.size.param) side = std::get<int64_t>(values[*slot.size.param]);
    if (slot.size.height_param) height = std::get<int64_t>(values[*slot.size.height_param]);
    if (slot.size.depth_param) depth = std::get<int64_t>(values[*slot.size.depth_param]);
    if (slot.size.divisor_param) divisor = divisor_of(slot.size, values[*slot.size.divisor_param]);
    SlotDecl effective = slot;
    if (const OutputOverride* o = overrides_[p][size_t(decl.slot_index(slot.name))]) {
      if (o->format) effective.format = *o->format;
      const auto it = sizes_resolved_.find({config_.passes[p].name, slot.name});
      if (it != sizes_resolved_.end()) effective.size = it->second;
    }
    *rule = {effective.kind != ResourceKind::buffer, effective.size, side, divisor, depth, height, mips, kNone};
    return resolve_slot(decl, effective, config_.output_size, side, divisor, depth, height, mips);
  }

  const Config& config_;
  const PassRegistry& registry_;
  const SizeNodes& sizes_;
  Diagnostics& diags_;
  std::map<std::string, uint32_t> index_;
  std::vector<const PassDecl*> decls_;
  std::vector<uint16_t> variants_;
  std::vector<std::vector<ParamValue>> params_;
  std::vector<std::vector<const OutputOverride*>> overrides_;
  std::vector<std::vector<std::optional<SlotRef>>> inputs_;
  std::vector<std::vector<Where>> wiring_where_;
  std::vector<std::optional<SlotRef>> outputs_;
  std::map<std::pair<std::string, std::string>, SizeSpec> sizes_resolved_;
  std::vector<std::vector<uint32_t>> steps_;  // per config pass: its graph passes (itself, or its steps; kNone: a step that does not run)
};

void apply_overrides(Config& config, const Overrides& o, Diagnostics& diags) {
  auto find_pass = [&](const std::string& name, const std::string& flag) -> PassNode* {
    for (PassNode& p : config.passes) {
      if (p.name == name) return &p;
    }
    diags.error({kCommandLine.file, flag, 0}, "no pass named \"" + name + "\"" + did_you_mean(name, names_of(config.passes)));
    return nullptr;
  };
  if (o.size) config.output_size = *o.size;
  for (const std::string& v : o.variants) {
    const std::string flag = "--variant " + v;
    const size_t eq = v.find('=');
    if (eq == std::string::npos || eq + 1 == v.size()) {
      diags.error({kCommandLine.file, flag, 0}, "expected --variant PASS=VARIANT with a variant's name");
      continue;
    }
    if (PassNode* p = find_pass(v.substr(0, eq), flag)) {
      p->variant = v.substr(eq + 1);
      p->variant_where = {kCommandLine.file, flag, 0};
    }
  }
  for (const std::string& s : o.sets) {
    const std::string flag = "--set " + s;
    const size_t dot = s.find('.'), eq = s.find('=');
    if (dot == std::string::npos || eq == std::string::npos || eq < dot) {
      diags.error({kCommandLine.file, flag, 0}, "expected --set PASS.PARAM=VALUE");
      continue;
    }
    PassNode* p = find_pass(s.substr(0, dot), flag);
    if (!p) continue;
    const std::string text = s.substr(eq + 1);
    Json value = Json::parse(text, nullptr, false);
    if (value.is_discarded()) value = text;  // a bare word is a string (a choice)
    Source src{kCommandLine.file, ".", {}};
    Diagnostics local;
    const Node node(src, value, flag, local);
    if (auto raw = raw_param(node)) set_param(*p, {s.substr(dot + 1, eq - dot - 1), *raw, {kCommandLine.file, flag, 0}});
    else diags.error({kCommandLine.file, flag, 0}, "VALUE must be a boolean, number, string or [x, y, z]");
  }
}

LoadedConfig load(const std::string& name, const std::string* text, const PassRegistry& registry, const Overrides& o) {
  Config config;
  config.file = name;
  Loader loader(config);
  loader.load_file(name, text, 0, {});
  loader.diagnostics().throw_if_any();
  if (!o.graph.empty()) loader.replace_graph(o.graph, {kCommandLine.file, "--graph " + o.graph, 0});
  loader.diagnostics().throw_if_any();
  apply_overrides(config, o, loader.diagnostics());
  loader.diagnostics().throw_if_any();
  registry.annotate(config.scene);
  return Wiring(config, registry, loader.sizes(), loader.diagnostics()).run();
}

}  // namespace

LoadedConfig load_config(const std::string& path, const PassRegistry& registry, const Overrides& overrides) {
  return load(path, nullptr, registry, overrides);
}

LoadedConfig load_config_text(const std::string& name, const std::string& text, const PassRegistry& registry,
                              const Overrides& overrides) {
  return load(name, &text, registry, overrides);
}

namespace {

bool is_attachment(Usage u) {
  return u == Usage::color_attachment || u == Usage::color_attachment_load || u == Usage::depth_attachment ||
         u == Usage::depth_read;
}

std::string extent_text(const Extent& e) { return std::to_string(e.width) + "x" + std::to_string(e.height); }

// The attachments of one render pass must have one size (Vulkan and WebGPU render into
// them together); an output's size override can break that.
void check_attachments_agree(const LoadedConfig& loaded) {
  const Graph& graph = loaded.graph;
  for (uint32_t g = 0; g < graph.passes.size(); ++g) {
    const GraphPass& pass = graph.passes[g];
    const ResourceUse* first = nullptr;
    for (const ResourceUse& u : pass.uses) {
      if (!is_attachment(u.usage) || u.resource == kNone) continue;
      if (!first) {
        first = &u;
        continue;
      }
      const Extent a = graph.resources[first->resource].desc.extent, b = graph.resources[u.resource].desc.extent;
      if (a.width == b.width && a.height == b.height) continue;
      const uint32_t p = pass.group != kNone ? pass.group : g;
      Where where{loaded.config.file, "/graph/passes", 0};
      if (p < loaded.config.passes.size()) {
        const PassNode& node = loaded.config.passes[p];
        where = node.where;
        for (const OutputOverride& o : node.outputs) {
          if (o.slot == pass.decl->slots[u.slot].name || o.slot == pass.decl->slots[first->slot].name) where = o.where;
        }
      }
      const std::string name = pass.group != kNone ? pass.name.substr(0, pass.name.find('/')) : pass.name;
      throw ConfigError({{where, "pass \"" + name + "\": its render targets differ in size: \"" +
                                     pass.decl->slots[first->slot].name + "\" is " + extent_text(a) + ", \"" +
                                     pass.decl->slots[u.slot].name + "\" " + extent_text(b) +
                                     "; the attachments of one render pass must have one size"}});
    }
  }
}

}  // namespace

Plan compile_loaded(const LoadedConfig& loaded, const CompileOptions& options, const RequirementsFn& requirements) {
  check_attachments_agree(loaded);
  try {
    return compile(loaded.graph, options, requirements);
  } catch (const GraphError& e) {
    Where where{loaded.config.file, "/graph/passes", 0};
    if (e.pass < loaded.config.passes.size()) where = loaded.config.passes[e.pass].where;
    throw ConfigError({{where, e.what()}});
  }
}

}  // namespace volgraph
