// Reading a sweep spec (sweep_spec.h): the document checked with the config loader's
// JSON reader (one diagnostic a mistake: file, JSON pointer, line, expectation), the
// series expanded into points, and every point loaded once against the config.
#include "tools/compare/sweep_spec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "graph/config/json_lines.h"
#include "graph/config/json_reader.h"
#include "tools/compare/metrics.h"
#include "tools/compare/render_setting.h"

namespace volgraph::compare {
namespace {

using config::Json;
using config::Node;
using config::Source;
using config::valid_name;

constexpr int64_t kMaxSide = 16384;
// 2^53: the integers of a range stay integers below it (a parameter reads them as doubles too).
constexpr double kLargestExactInteger = 9007199254740992.0;

// An integer as written (16, not 16.0), small enough to stay exact.
bool integral(const Json& j) { return j.is_number_integer() && std::abs(j.get<double>()) < kLargestExactInteger; }

const std::vector<std::string> kBackends{"vulkan", "webgpu"};
const std::vector<std::string> kReferenceModes{"straight", "refracted"};

// A value rounded to 12 significant digits, so that a range's 0.1 + 2 × 0.1 is 0.3.
double round_12_digits(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return std::strtod(buf, nullptr);
}

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// What a value shows as in a label: a string without its quotes, anything else as JSON.
std::string display_text(const Json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// FNV-1a, 64 bits (Fowler, Noll, Vo; offset basis 14695981039346656037, prime 1099511628211).
uint64_t fnv1a_64(const std::string& bytes) {
  uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

// What a key of "set" or "vary" sets: a pass's variant ("PASS"), a parameter
// ("PASS.PARAM"), or the frames rendered before the image is measured ("frames").
enum class Kind { variant, param, frames };

constexpr const char* kFramesKey = "frames";
constexpr int64_t kMaxFrames = 1000;

// A key of "set" or "vary" and the values it takes.
struct Axis {
  std::string key;
  Kind kind = Kind::param;
  std::vector<Json> values;
  std::string pointer;  // of the key, for the config's refusals
  bool listed = false;  // the values are an array written out (not a range): each has its own pointer
};

struct Series {
  std::string name;
  std::string graph_as_written, graph;
  std::vector<Axis> sets, varies;
  std::string pointer;
};

class SpecReader {
 public:
  SpecReader(const std::string& path, const PassRegistry& registry) : registry_(registry) {
    source_.file = path;
    source_.dir = std::filesystem::path(path).parent_path().string();
    spec_.file = path;
  }

  SweepSpec read() {
    const std::optional<Json> json = parse();
    diags_.throw_if_any();
    read_document(Node(source_, *json, "", diags_));
    diags_.throw_if_any();
    expand();
    diags_.throw_if_any();
    check_against_config();
    diags_.throw_if_any();
    return std::move(spec_);
  }

 private:
  std::optional<Json> parse() {
    const std::string& path = source_.file;
    std::string text;
    if (const std::string problem = config::read_text_file(path, text); !problem.empty()) {
      diags_.error({path, "", 0}, "cannot read \"" + path + "\": " + problem);
      return std::nullopt;
    }
    std::optional<Json> json = config::parse_json_document(path, text, diags_);
    if (!json) return std::nullopt;
    source_.lines = index_json_lines(text);
    return json;
  }

  void read_document(const Node& doc) {
    if (!doc.object({"description", "config", "size", "runs", "warmup", "frames", "backend", "reference", "reference_mode", "metric",
                     "mask", "series"})) {
      return;
    }
    config::read(doc, "description", spec_.description);
    if (auto c = doc.member("config")) {
      if (auto path = c->existing_path()) spec_.config = *path;
    } else {
      doc.error("missing \"config\": expected the config file the sweep renders (relative to the spec's folder)");
    }
    if (auto s = doc.member("size")) read_size(*s);
    read_count(doc, "runs", spec_.runs, 1, 1000);
    read_count(doc, "warmup", spec_.warmup, 0, 100);
    read_count(doc, "frames", spec_.frames, 1, 1000);
    if (auto b = doc.member("backend")) {
      if (auto name = choice(*b, kBackends, "backend")) spec_.backend = *name;
    }
    if (auto r = doc.member("reference")) read_reference(*r);
    if (auto m = doc.member("reference_mode")) {
      if (auto name = choice(*m, kReferenceModes, "reference_mode")) spec_.reference_mode = *name;
    }
    if (auto m = doc.member("metric")) read_metric(*m);
    if (auto m = doc.member("mask")) {
      if (auto name = choice(*m, mask_names(), "mask")) spec_.mask = *name;
    }
    if (auto s = doc.member("series")) {
      read_series_list(*s);
    } else {
      doc.error("missing \"series\": expected an array of series, each {\"name\", \"graph\", \"set\", \"vary\"}");
    }
  }

  void read_size(const Node& n) {
    if (!n.json().is_array() || n.size() != 2) {
      n.error("expected [width, height] in pixels, got " + config::describe(n.json()));
      return;
    }
    const auto w = n.element(0).integer(1, kMaxSide), h = n.element(1).integer(1, kMaxSide);
    if (w && h) spec_.size = Extent{uint32_t(*w), uint32_t(*h), 1};
  }

  static void read_count(const Node& doc, const char* key, int& out, int64_t min, int64_t max) {
    if (auto n = doc.member(key)) {
      if (auto v = n->integer(min, max)) out = int(*v);
    }
  }

  static std::optional<std::string> choice(const Node& n, const std::vector<std::string>& names, const char* what) {
    const auto text = n.string();
    if (!text) return std::nullopt;
    if (std::find(names.begin(), names.end(), *text) != names.end()) return text;
    n.error("unknown " + std::string(what) + " \"" + *text + "\"" + did_you_mean(*text, names) + "; expected " + one_of(names));
    return std::nullopt;
  }

  void read_reference(const Node& n) {
    const auto text = n.string();
    if (!text) return;
    if (*text == "cpu") {
      spec_.reference = "cpu";
      return;
    }
    std::string ext = std::filesystem::path(*text).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".pfm" && ext != ".exr") {
      n.error("expected \"cpu\" (the CPU reference renderer) or a linear image file (.pfm or .exr), got \"" + *text + "\"");
      return;
    }
    if (auto path = n.existing_path()) spec_.reference = *path;
  }

  void read_metric(const Node& n) {
    const auto text = n.string();
    if (!text) return;
    if (is_metric_name(*text)) {
      spec_.metric = *text;
      return;
    }
    n.error("unknown metric \"" + *text + "\"" + did_you_mean(*text, metric_names()) + "; expected " + one_of(metric_names()));
  }

  void read_series_list(const Node& list) {
    if (!list.json().is_array() || list.size() == 0) {
      list.error("expected a non-empty array of series, each {\"name\", \"graph\", \"set\", \"vary\"}, got " +
                 config::describe(list.json()));
      return;
    }
    std::map<std::string, std::string> names;  // name → pointer of its first series
    for (size_t i = 0; i < list.size(); ++i) {
      const Node n = list.element(i);
      if (auto s = read_series(n)) {
        const auto [it, fresh] = names.emplace(s->name, n.pointer());
        if (!fresh) {
          n.child("name").error("series name \"" + s->name + "\" is taken by " + it->second + "; expected a unique name");
          continue;
        }
        series_.push_back(std::move(*s));
      }
    }
  }

  std::optional<Series> read_series(const Node& n) {
    if (!n.object({"name", "graph", "set", "vary"})) return std::nullopt;
    Series s;
    s.pointer = n.pointer();
    bool ok = true;
    if (auto name = n.member("name")) {
      const auto text = name->string();
      if (text && text->empty()) name->error("expected a series name, got an empty string");
      if (!text || text->empty()) ok = false;
      else s.name = *text;
    } else {
      n.error("missing \"name\": expected the series' name (a string, unique in the spec)");
      ok = false;
    }
    if (auto g = n.member("graph")) {
      const auto written = g->string();
      const auto path = written ? g->existing_path() : std::nullopt;
      if (path) {
        s.graph_as_written = *written;
        s.graph = *path;
      } else {
        ok = false;
      }
    }
    if (auto set = n.member("set")) ok = read_sets(*set, s.sets) && ok;
    if (auto vary = n.member("vary")) ok = read_varies(*vary, s.sets, s.varies) && ok;
    return ok ? std::optional(std::move(s)) : std::nullopt;
  }

  // A key "frames", "PASS" (variant) or "PASS.PARAM" (parameter); nullopt (reported) when none.
  static std::optional<Kind> kind_of(const Node& key_node, const std::string& key) {
    if (key == kFramesKey) return Kind::frames;
    const size_t dot = key.find('.');
    const bool variant = dot == std::string::npos;
    const bool ok = variant ? valid_name(key) : valid_name(key.substr(0, dot)) && valid_name(key.substr(dot + 1));
    if (ok) return variant ? Kind::variant : Kind::param;
    key_node.error("expected a key \"PASS\" (picks a variant), \"PASS.PARAM\" (sets a parameter) or \"frames\", names of "
                   "letters, digits and '_', got \"" + key + "\"");
    return std::nullopt;
  }

  // A value a key takes: a variant's name, or a parameter value as --set takes it.
  static bool value_fits(const Node& v, Kind kind, const std::string& key) {
    const Json& j = v.json();
    if (kind == Kind::frames) return bool(v.integer(1, kMaxFrames));
    if (kind == Kind::variant) {
      if (j.is_string() && !j.get<std::string>().empty()) return true;
      v.error("expected the name of a variant of pass \"" + key + "\" (a string), got " + config::describe(j));
      return false;
    }
    const bool vec3 = j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number();
    if (j.is_boolean() || j.is_number() || j.is_string() || vec3) return true;
    v.error("expected a value for parameter \"" + key + "\": true or false, a number, a string or [x, y, z], got " +
            config::describe(j));
    return false;
  }

  static bool read_sets(const Node& set, std::vector<Axis>& out) {
    if (!set.object_any_keys()) return false;
    bool ok = true;
    for (const auto& item : set.json().items()) {
      const Node v = set.child(item.key());
      const auto kind = kind_of(v, item.key());
      if (!kind || !value_fits(v, *kind, item.key())) {
        ok = false;
        continue;
      }
      out.push_back({item.key(), *kind, {v.json()}, v.pointer()});
    }
    return ok;
  }

  bool read_varies(const Node& vary, const std::vector<Axis>& sets, std::vector<Axis>& out) {
    if (!vary.object_any_keys()) return false;
    bool ok = true;
    for (const auto& item : vary.json().items()) {
      const Node v = vary.child(item.key());
      const auto kind = kind_of(v, item.key());
      if (!kind) {
        ok = false;
        continue;
      }
      const auto in_set = std::find_if(sets.begin(), sets.end(), [&](const Axis& a) { return a.key == item.key(); });
      if (in_set != sets.end()) {
        v.error("\"" + item.key() + "\" is in \"set\" too (" + in_set->pointer + "); expected a key either set or varied");
        ok = false;
        continue;
      }
      Axis axis{item.key(), *kind, {}, v.pointer()};
      if (!read_vary_values(v, axis)) {
        ok = false;
        continue;
      }
      out.push_back(std::move(axis));
    }
    return ok;
  }

  bool read_vary_values(const Node& v, Axis& axis) {
    const Json& j = v.json();
    if (j.is_object()) {
      if (axis.kind == Kind::variant) {
        v.error("a range needs a parameter key \"PASS.PARAM\" or \"frames\"; \"" + axis.key +
                "\" picks a variant: expected an array of variant names");
        return false;
      }
      return read_range(v, axis.values) && (axis.kind != Kind::frames || frame_counts(v, axis.values));
    }
    if (!j.is_array() || j.empty()) {
      v.error("expected a non-empty array of values, or a range {\"from\", \"to\", \"times\"} or {\"from\", \"to\", \"step\"}, got " +
              config::describe(j));
      return false;
    }
    for (size_t i = 0; i < v.size(); ++i) {
      const Node e = v.element(i);
      if (!value_fits(e, axis.kind, axis.key)) return false;
      const auto same = std::find(axis.values.begin(), axis.values.end(), e.json());
      if (same != axis.values.end()) {
        e.error("the value " + e.json().dump() + " is listed twice (first at " + v.pointer() + "/" +
                std::to_string(same - axis.values.begin()) + "); expected distinct values");
        return false;
      }
      axis.values.push_back(e.json());
    }
    axis.listed = true;
    return true;
  }

  // A range of "frames": whole numbers in [1, kMaxFrames].
  static bool frame_counts(const Node& r, const std::vector<Json>& values) {
    for (const Json& v : values) {
      if (v.is_number_integer() && v.get<int64_t>() >= 1 && v.get<int64_t>() <= kMaxFrames) continue;
      r.error("expected a range of frame counts, integers in [1, " + std::to_string(kMaxFrames) + "] (\"from\" and \"" +
              (r.json().contains("times") ? "times" : "step") + "\" written as integers), got " + v.dump());
      return false;
    }
    return true;
  }

  // {"from", "to", "times"}: from, from·times, from·times², … ≤ to;
  // {"from", "to", "step"}: from, from + step, … ≤ to (to included within 1e-9 of a step).
  static bool read_range(const Node& r, std::vector<Json>& out) {
    if (!r.object({"from", "to", "times", "step"})) return false;
    const auto times_node = r.member("times"), step_node = r.member("step");
    const auto from_node = r.member("from"), to_node = r.member("to");
    if (!from_node || !to_node || bool(times_node) == bool(step_node)) {
      r.error("expected a range {\"from\", \"to\", \"times\"} (geometric) or {\"from\", \"to\", \"step\"} (arithmetic)");
      return false;
    }
    const auto from = above(*from_node, times_node ? std::optional(0.0) : std::nullopt, "from", "a geometric range starts above 0");
    if (!from) return false;
    const auto to = at_least(*to_node, *from);
    if (!to) return false;
    if (times_node) {
      const auto times = above(*times_node, 1.0, "times", "a geometric range grows");
      if (!times) return false;
      const double count = std::floor(std::log(*to / *from) / std::log(*times) + 1e-9) + 1;
      if (!count_fits(r, count)) return false;
      if (integral(from_node->json()) && integral(times_node->json()) && *to < kLargestExactInteger) {
        geometric_integers(from_node->json().get<int64_t>(), times_node->json().get<int64_t>(), *to, out);
      } else {
        geometric(*from, *times, *to, out);
      }
      return true;
    }
    const auto step = above(*step_node, 0.0, "step", "an arithmetic range grows");
    if (!step) return false;
    const double count = std::floor((*to - *from) / *step + 1e-9) + 1;
    if (!count_fits(r, count)) return false;
    const bool integers = integral(from_node->json()) && integral(step_node->json()) &&
                          std::abs(*from) + (count - 1) * *step < kLargestExactInteger;
    for (int64_t i = 0; i < int64_t(count); ++i) {
      if (integers) {
        out.emplace_back(from_node->json().get<int64_t>() + i * step_node->json().get<int64_t>());
        continue;
      }
      const double v = round_12_digits(*from + double(i) * *step);
      out.emplace_back(std::abs(v - *to) <= 1e-9 * *step ? *to : v);
    }
    return true;
  }

  // A finite number, above `bound` when there is one.
  static std::optional<double> above(const Node& n, std::optional<double> bound, const char* key, const char* why) {
    const Json& j = n.json();
    const bool fits = j.is_number() && std::isfinite(j.get<double>()) && (!bound || j.get<double>() > *bound);
    if (fits) return j.get<double>();
    const std::string expected = bound ? "a number > " + number_text(*bound) + " (" + why + ")" : "a finite number";
    n.error("expected \"" + std::string(key) + "\" " + expected + ", got " + config::describe(j));
    return std::nullopt;
  }

  static std::optional<double> at_least(const Node& n, double from) {
    const Json& j = n.json();
    if (j.is_number() && std::isfinite(j.get<double>()) && j.get<double>() >= from) return j.get<double>();
    n.error("expected \"to\" a number ≥ \"from\" (" + number_text(from) + "), got " + config::describe(j));
    return std::nullopt;
  }

  static bool count_fits(const Node& r, double count) {
    if (count <= double(kMaxSweepPoints)) return true;
    r.error("the range expands to " + (std::isfinite(count) && count < 1e15 ? std::to_string(int64_t(count)) : "too many") +
            " values; expected at most " + std::to_string(kMaxSweepPoints));
    return false;
  }

  static void geometric_integers(int64_t from, int64_t times, double to, std::vector<Json>& out) {
    for (int64_t v = from; double(v) <= to; v *= times) {
      out.emplace_back(v);
      if (double(v) * double(times) > to) return;  // the next is past the end (and may not fit an int64)
    }
  }

  static void geometric(double from, double times, double to, std::vector<Json>& out) {
    for (int i = 0; i <= int(kMaxSweepPoints); ++i) {
      const double v = round_12_digits(from * std::pow(times, i));
      if (v > to * (1 + 1e-9)) return;
      out.emplace_back(std::abs(v - to) <= 1e-9 * to ? to : v);
    }
  }

  void expand() {
    size_t total = 0;
    for (const Series& s : series_) {
      size_t count = 1;
      std::string product;
      for (const Axis& a : s.varies) {
        count = count > kMaxSweepPoints ? count : count * a.values.size();
        product += (product.empty() ? "" : " × ") + std::to_string(a.values.size());
      }
      if (count > kMaxSweepPoints) {
        diags_.error(where(s.pointer), "series \"" + s.name + "\" expands to " + product + " points, more than " +
                                           std::to_string(kMaxSweepPoints) + "; expected fewer values to vary");
        continue;
      }
      total += count;
      if (total > kMaxSweepPoints) {
        diags_.error(where(s.pointer), "the series up to \"" + s.name + "\" expand to " + std::to_string(total) +
                                           " points, more than " + std::to_string(kMaxSweepPoints) + "; expected fewer");
        return;
      }
      expand_series(s, count);
    }
  }

  void expand_series(const Series& s, size_t count) {
    std::vector<size_t> index(s.varies.size(), 0);
    for (size_t n = 0; n < count; ++n) {
      add_point(s, index);
      for (size_t k = index.size(); k-- > 0;) {  // the last key fastest
        if (++index[k] < s.varies[k].values.size()) break;
        index[k] = 0;
      }
    }
  }

  void add_point(const Series& s, const std::vector<size_t>& index) {
    SweepPoint p;
    p.frames = spec_.frames;
    p.series = s.name;
    p.graph = s.graph;
    p.overrides.graph = s.graph;
    auto add = [&](const Axis& a, const Json& value) {
      const std::string text = value.dump();
      p.settings.emplace_back(a.key, text);
      if (a.kind == Kind::frames) p.frames = int(value.get<int64_t>());
      else if (a.kind == Kind::variant) p.overrides.variants.push_back(a.key + "=" + value.get<std::string>());
      else p.overrides.sets.push_back(a.key + "=" + text);
    };
    for (const Axis& a : s.sets) add(a, a.values.front());
    for (size_t k = 0; k < s.varies.size(); ++k) {
      const Json& value = s.varies[k].values[index[k]];
      add(s.varies[k], value);
      p.label += (k ? ", " : "") + s.varies[k].key + "=" + display_text(value);
    }
    if (p.label.empty()) p.label = s.name;
    p.id = sweep_point_id(s.name, s.graph_as_written, p.settings);
    const auto [it, fresh] = ids_.emplace(p.id, spec_.points.size());
    if (!fresh) {
      const SweepPoint& first = spec_.points[it->second];
      diags_.error(where(s.pointer), "point \"" + p.label + "\" has the id " + p.id + " of series \"" + first.series +
                                         "\"'s point \"" + first.label + "\"; expected every point of a spec distinct");
      return;
    }
    const auto [same, new_render] = renders_.emplace(render_key(s, p), spec_.points.size());
    if (!new_render) {
      const SweepPoint& first = spec_.points[same->second];
      if (repeats_reported_.emplace(s.name, first.series).second) {
        diags_.error(where(s.pointer), "series \"" + s.name + "\"'s point \"" + p.label + "\" renders what series \"" +
                                           first.series + "\"'s point \"" + first.label +
                                           "\" does (the same graph, settings and frames); expected every point of a spec distinct");
      }
      return;
    }
    point_series_.push_back(&s);
    spec_.points.push_back(std::move(p));
  }

  // What a point renders, whatever its series and the order of its settings: the graph
  // file, the frames and the settings sorted by key, numbers that are whole written as integers.
  std::string render_key(const Series& s, const SweepPoint& p) const {
    std::error_code ec;
    std::string graph = s.graph.empty() ? "" : std::filesystem::weakly_canonical(s.graph, ec).string();
    if (ec) graph = s.graph;
    std::vector<std::pair<std::string, std::string>> settings;
    for (const auto& [key, text] : p.settings) {
      if (key != kFramesKey) settings.emplace_back(key, whole_numbers_as_integers(Json::parse(text)).dump());
    }
    std::sort(settings.begin(), settings.end());
    std::string out = graph + "\nframes=" + std::to_string(p.frames) + "\n";
    for (const auto& [key, text] : settings) out += key + "=" + text + "\n";
    return out;
  }

  static Json whole_numbers_as_integers(Json v) {
    if (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>() && std::abs(v.get<double>()) < kLargestExactInteger) {
      return Json(int64_t(v.get<double>()));
    }
    if (v.is_array()) {
      for (Json& e : v) e = whole_numbers_as_integers(e);
    }
    return v;
  }

  Where where(const std::string& pointer) const {
    const auto it = source_.lines.find(pointer);
    return {source_.file, pointer.empty() ? "/" : pointer, it == source_.lines.end() ? 0 : it->second};
  }

  static std::string joined(const std::vector<Diagnostic>& list) {
    std::string out;
    for (const Diagnostic& d : list) out += (out.empty() ? "" : "; ") + format_diagnostic(d);
    return out;
  }

  // What the config refuses at one point, and where in the spec.
  struct Refusal {
    const Series* series;
    std::string key_pointer;    // the series' key that sets it, else the series
    std::string value_pointer;  // that key's value at the point (its element when listed)
    std::string value;          // the value's text in the loader's flag ("" when no key is named)
    std::string label;          // the point's
    std::string loader;         // the loader's message, with the flag it names
    std::string cause;          // the same without the flag: what groups refusals
  };

  // Every point loaded once against the config: what the config refuses (no such pass,
  // a parameter out of range, an unknown variant) is reported at the series' key that
  // sets it when the loader names the flag, else at the series; one refusal is one message,
  // at the key's value when one value makes it, at the key when several do.
  void check_against_config() {
    try {
      load_config(spec_.config, registry_);
    } catch (const ConfigError& e) {
      diags_.error(where("/config"), "the config does not load: " + joined(e.diagnostics()));
      return;
    }
    std::vector<Refusal> refusals;
    for (size_t i = 0; i < spec_.points.size(); ++i) {
      const SweepPoint& p = spec_.points[i];
      Overrides o = p.overrides;
      o.size = spec_.size;
      try {
        load_config(spec_.config, registry_, o);
      } catch (const ConfigError& e) {
        for (const Diagnostic& d : e.diagnostics()) refusals.push_back(refusal(*point_series_[i], p, d));
      } catch (const std::exception& e) {
        refusals.push_back(refusal(*point_series_[i], p, Diagnostic{{spec_.config, "", 0}, e.what()}));
      }
    }
    report(refusals);
  }

  static Refusal refusal(const Series& s, const SweepPoint& p, const Diagnostic& d) {
    Refusal r{&s, s.pointer, s.pointer, "", p.label, format_diagnostic(d), format_diagnostic(d)};
    if (d.where.file != "<command line>") return r;
    r.loader = d.where.pointer + ": " + d.message;
    r.cause = d.message;
    for (const auto* axes : {&s.sets, &s.varies}) {
      for (const Axis& a : *axes) {
        const std::string prefix = (a.kind == Kind::variant ? "--variant " : "--set ") + a.key + "=";
        if (d.where.pointer.rfind(prefix, 0) != 0) continue;
        r.key_pointer = a.pointer;
        r.value_pointer = pointer_of_value(a, p);
        r.value = d.where.pointer.substr(prefix.size());
      }
    }
    return r;
  }

  void report(const std::vector<Refusal>& refusals) {
    std::vector<bool> done(refusals.size(), false);
    for (size_t i = 0; i < refusals.size(); ++i) {
      if (done[i]) continue;
      const Refusal& first = refusals[i];
      std::vector<std::string> values;  // the distinct values of the key that make the same refusal
      for (size_t j = i; j < refusals.size(); ++j) {
        const Refusal& r = refusals[j];
        if (r.series != first.series || r.key_pointer != first.key_pointer || r.cause != first.cause) continue;
        done[j] = true;
        if (std::find(values.begin(), values.end(), r.value) == values.end()) values.push_back(r.value);
      }
      if (values.size() == 1) {
        diags_.error(where(first.value_pointer), "the config refuses series \"" + first.series->name + "\"'s point \"" +
                                                     first.label + "\": " + first.loader);
        continue;
      }
      std::string list;
      for (const std::string& v : values) list += (list.empty() ? "" : ", ") + v;
      const std::string key = first.key_pointer.substr(first.key_pointer.rfind('/') + 1);
      diags_.error(where(first.key_pointer), "the config refuses series \"" + first.series->name + "\"'s \"" + key +
                                                 "\" at the values " + list + ": " + first.loader);
    }
  }

  // The pointer of the value `a` takes at point `p`: its element when the values are listed.
  static std::string pointer_of_value(const Axis& a, const SweepPoint& p) {
    if (!a.listed) return a.pointer;
    const auto setting = std::find_if(p.settings.begin(), p.settings.end(), [&](const auto& s) { return s.first == a.key; });
    for (size_t i = 0; setting != p.settings.end() && i < a.values.size(); ++i) {
      if (a.values[i].dump() == setting->second) return a.pointer + "/" + std::to_string(i);
    }
    return a.pointer;
  }

  const PassRegistry& registry_;
  Source source_;
  Diagnostics diags_;
  SweepSpec spec_;
  std::vector<Series> series_;
  std::vector<const Series*> point_series_;  // per point
  std::map<std::string, size_t> ids_;        // id → point index
  std::map<std::string, size_t> renders_;    // render_key → point index
  std::set<std::pair<std::string, std::string>> repeats_reported_;  // (series, series it repeats)
};

}  // namespace

std::string sweep_point_id(const std::string& series, const std::string& graph_as_written,
                           const std::vector<std::pair<std::string, std::string>>& settings) {
  std::string bytes = series + "\n" + graph_as_written + "\n";
  for (const auto& [key, text] : settings) bytes += key + "=" + text + "\n";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%012llx", static_cast<unsigned long long>(fnv1a_64(bytes) & 0xffffffffffffull));
  return buf;
}

SweepSpec read_sweep_spec(const std::string& path, const PassRegistry& registry) {
  return SpecReader(path, registry).read();
}

}  // namespace volgraph::compare
