// A sweep point's result file (JSON), the point files of a sweep folder, and the
// Pareto front of time against error per device.
#include "tools/compare/sweep_results.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "graph/diagnostics.h"
#include "tools/compare/figures_json.h"
#include "tools/output_files.h"

namespace volgraph::compare {
namespace {

// Reads a point file, each failure naming the file and the JSON pointer of the value.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& expected) const {
    throw ConfigError({{{file_, pointer.empty() ? "/" : pointer, 0}, expected}});  // a damaged folder is bad input
  }

  const Json& member(const Json& object, const std::string& pointer, const std::string& key) const {
    if (!object.is_object()) fail(pointer, "expected an object");
    auto found = object.find(key);
    if (found == object.end()) fail(pointer, "missing \"" + key + "\"");
    return *found;
  }
  std::string string(const Json& object, const std::string& pointer, const std::string& key) const {
    const Json& value = member(object, pointer, key);
    if (!value.is_string()) fail(pointer + "/" + key, "expected a string");
    return value.get<std::string>();
  }
  bool boolean(const Json& object, const std::string& pointer, const std::string& key) const {
    const Json& value = member(object, pointer, key);
    if (!value.is_boolean()) fail(pointer + "/" + key, "expected true or false");
    return value.get<bool>();
  }
  double real(const Json& object, const std::string& pointer, const std::string& key) const {
    const Json& value = member(object, pointer, key);
    if (value.is_number()) return value.get<double>();
    if (value == "inf") return std::numeric_limits<double>::infinity();
    if (value == "-inf") return -std::numeric_limits<double>::infinity();
    if (value == "nan") return std::numeric_limits<double>::quiet_NaN();
    fail(pointer + "/" + key, "expected a number (or \"inf\", \"-inf\", \"nan\")");
  }
  uint64_t count(const Json& object, const std::string& pointer, const std::string& key) const {
    const Json& value = member(object, pointer, key);
    if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<int64_t>() >= 0)) {
      fail(pointer + "/" + key, "expected a whole number ≥ 0");
    }
    return value.get<uint64_t>();
  }
  int integer(const Json& object, const std::string& pointer, const std::string& key) const {
    const Json& value = member(object, pointer, key);
    if (!value.is_number_integer()) fail(pointer + "/" + key, "expected a whole number");
    return value.get<int>();
  }

 private:
  std::string file_;
};

Spread read_spread(const Reader& r, const Json& object, const std::string& pointer, const std::string& key) {
  const Json& j = r.member(object, pointer, key);
  const std::string at = pointer + "/" + key;
  return {r.real(j, at, "median"), r.real(j, at, "min"), r.real(j, at, "max"), r.integer(j, at, "runs")};
}

TimingSummary read_timing(const Reader& r, const Json& j, const std::string& at) {
  TimingSummary t;
  t.runs = r.integer(j, at, "runs");
  t.warmup = r.integer(j, at, "warmup");
  t.frame_wall_ms = read_spread(r, j, at, "frame_wall_ms");
  const Json& passes = r.member(j, at, "passes");
  if (!passes.is_array()) r.fail(at + "/passes", "expected an array");
  for (size_t i = 0; i < passes.size(); ++i) {
    const std::string pass_at = at + "/passes/" + std::to_string(i);
    t.passes.push_back({r.string(passes[i], pass_at, "pass"), r.string(passes[i], pass_at, "type"),
                        read_spread(r, passes[i], pass_at, "gpu_ms"), read_spread(r, passes[i], pass_at, "cpu_ms")});
  }
  t.gpu_timestamps = r.boolean(j, at, "gpu_timestamps");
  t.clock = r.string(j, at, "clock");
  return t;
}

MemorySummary read_memory(const Reader& r, const Json& j, const std::string& at) {
  MemorySummary m;
  m.aliased_bytes = r.count(j, at, "aliased_bytes");
  m.unaliased_bytes = r.count(j, at, "unaliased_bytes");
  m.lower_bound_bytes = r.count(j, at, "lower_bound_bytes");
  m.persistent_bytes = r.count(j, at, "persistent_bytes");
  m.passes_run = uint32_t(r.count(j, at, "passes_run"));
  m.passes_culled = uint32_t(r.count(j, at, "passes_culled"));
  return m;
}

ErrorMetrics read_metrics(const Reader& r, const Json& j, const std::string& at) {
  ErrorMetrics m;
  m.compared_pixels = r.count(j, at, "compared_pixels");
  m.nan_values = r.count(j, at, "nan_values");
  m.inf_values = r.count(j, at, "inf_values");
  m.rmse = r.real(j, at, "rmse");
  m.relative_rmse = r.real(j, at, "relative_rmse");
  m.psnr_db = r.real(j, at, "psnr_db");
  m.ssim = r.real(j, at, "ssim");
  m.flip = r.real(j, at, "flip");
  m.max_abs_error = r.real(j, at, "max_abs_error");
  m.relative_mean_error = r.real(j, at, "relative_mean_error");
  return m;
}

Json point_json(const PointResult& p) {
  Json settings = Json::object();
  for (const auto& [key, value] : p.settings) settings[key] = value;
  return Json{{"id", p.id},
              {"series", p.series},
              {"label", p.label},
              {"graph", p.graph},
              {"settings", settings},
              {"ok", p.ok},
              {"error", p.error},
              {"backend", p.backend},
              {"device", p.device},
              {"driver", p.driver},
              {"device_is_cpu", p.device_is_cpu},
              {"command", p.command},
              {"timing", timing_json(p.timing)},
              {"memory", memory_json(p.memory)},
              {"metrics", metrics_json(p.metrics)},
              {"metric", p.metric},
              {"seconds", number_json(p.seconds)},
              {"pareto", p.pareto}};
}

PointResult read_point(const Reader& r, const Json& j) {
  PointResult p;
  p.id = r.string(j, "", "id");
  p.series = r.string(j, "", "series");
  p.label = r.string(j, "", "label");
  p.graph = r.string(j, "", "graph");
  const Json& settings = r.member(j, "", "settings");
  if (!settings.is_object()) r.fail("/settings", "expected an object");
  for (auto it = settings.begin(); it != settings.end(); ++it) {
    if (!it.value().is_string()) r.fail("/settings/" + it.key(), "expected a string (the setting's JSON text)");
    p.settings.emplace_back(it.key(), it.value().get<std::string>());
  }
  p.ok = r.boolean(j, "", "ok");
  p.error = r.string(j, "", "error");
  p.backend = r.string(j, "", "backend");
  p.device = r.string(j, "", "device");
  p.driver = r.string(j, "", "driver");
  p.device_is_cpu = r.boolean(j, "", "device_is_cpu");
  p.command = r.string(j, "", "command");
  p.timing = read_timing(r, r.member(j, "", "timing"), "/timing");
  p.memory = read_memory(r, r.member(j, "", "memory"), "/memory");
  p.metrics = read_metrics(r, r.member(j, "", "metrics"), "/metrics");
  p.metric = r.string(j, "", "metric");
  p.seconds = r.real(j, "", "seconds");
  p.pareto = r.boolean(j, "", "pareto");
  return p;
}

std::span<const std::byte> bytes_of(const std::string& text) {
  return std::as_bytes(std::span(text.data(), text.size()));
}

// A point id names its file: it must not leave the points folder.
void check_id(const std::string& id) {
  const bool safe = !id.empty() && id.front() != '.' && id.find_first_of("/\\\n") == std::string::npos;
  if (!safe) throw std::invalid_argument("point id '" + id + "' cannot name a file");
}

// A file of the points folder, not a temporary of a write under way.
bool is_point_file(const std::filesystem::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  return entry.is_regular_file() && entry.path().extension() == ".json" && name.find(".tmp-") == std::string::npos &&
         name.front() != '.';
}

// Whether a point's figures are fit to be on the front: rendered, its time and error
// finite numbers, and no NaN or Inf in its image (the error figures leave those pixels out).
bool front_candidate(const PointResult& p) {
  if (!p.ok || p.metrics.nan_values || p.metrics.inf_values) return false;
  if (!std::isfinite(p.timing.frame_wall_ms.median)) return false;
  return !std::isnan(metric_value(p.metrics, p.metric));
}

// Whether `a` is at least as good as `b` in the metric, and strictly better.
int compare_error(double a, double b, bool lower_is_better) {
  if (a == b) return 0;
  return (a < b) == lower_is_better ? -1 : 1;
}

}  // namespace

std::string point_result_json(const PointResult& result) { return point_json(result).dump(2) + "\n"; }

PointResult parse_point_result(const std::string& text, const std::string& file) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::parse_error& e) {
    throw ConfigError({{{file, "", 0}, std::string("not JSON (") + e.what() + "); expected a point result (a damaged sweep folder: remove the file to run the point again)"}});
  }
  return read_point(Reader(file), j);
}

// Pareto optimality (a point not dominated in both objectives), within each device:
// times of different devices do not compare.
void mark_pareto(std::vector<PointResult>& results) {
  for (PointResult& p : results) p.pareto = false;
  for (PointResult& p : results) {
    if (!front_candidate(p)) continue;
    const bool lower = metric_lower_is_better(p.metric);
    const double p_time = p.timing.frame_wall_ms.median, p_error = metric_value(p.metrics, p.metric);
    const bool dominated = std::any_of(results.begin(), results.end(), [&](const PointResult& q) {
      if (&q == &p || q.device != p.device || !front_candidate(q)) return false;
      const double q_time = q.timing.frame_wall_ms.median, q_error = metric_value(q.metrics, p.metric);
      const int error = compare_error(q_error, p_error, lower);
      return q_time <= p_time && error <= 0 && (q_time < p_time || error < 0);
    });
    p.pareto = !dominated;
  }
}

PointResult read_point_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError({{{path.string(), "", 0}, "cannot be read; expected a point result"}});
  std::ostringstream text;
  text << in.rdbuf();
  return parse_point_result(text.str(), path.string());
}

void check_points_folder(const std::string& dir) {
  const std::filesystem::path folder = std::filesystem::path(dir) / "points";
  std::error_code ec;
  if (std::filesystem::exists(folder, ec) && !std::filesystem::is_directory(folder, ec)) {
    throw ConfigError({{{folder.string(), "", 0}, "is not a folder; expected the sweep's folder of point results"}});
  }
}

std::vector<PointResult> read_results(const std::string& dir) {
  check_points_folder(dir);
  const std::filesystem::path folder = std::filesystem::path(dir) / "points";
  std::vector<PointResult> results;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) return results;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (is_point_file(entry)) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) results.push_back(read_point_file(file));
  std::stable_sort(results.begin(), results.end(), [](const PointResult& a, const PointResult& b) {
    return std::tie(a.id, a.device) < std::tie(b.id, b.device);
  });
  return results;
}

// A point file never claims the front: that depends on the other points (results.json
// says it).
void save_point_as(const std::string& dir, const std::string& stem, const PointResult& result) {
  check_id(stem);
  const std::filesystem::path folder = std::filesystem::path(dir) / "points";
  std::filesystem::create_directories(folder);
  PointResult stored = result;
  stored.pareto = false;
  const std::string target = (folder / (stem + ".json")).string();
  const std::string temporary = target + ".tmp-" + std::to_string(::getpid());
  try {
    write_file_checked(temporary, bytes_of(point_result_json(stored)), target);
  } catch (const IoError&) {  // a full disk leaves no temporary behind
    std::error_code ec;
    std::filesystem::remove(temporary, ec);
    throw;
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    std::error_code ec;
    std::filesystem::remove(temporary, ec);
    throw IoError(target + ": cannot be renamed into place");
  }
}

void save_point(const std::string& dir, const PointResult& result) { save_point_as(dir, result.id, result); }

std::string device_hash(const std::string& device) {
  uint32_t hash = 2166136261u;  // FNV-1a, 32 bits (Fowler, Noll, Vo)
  for (unsigned char c : device) hash = (hash ^ c) * 16777619u;
  char text[9];
  std::snprintf(text, sizeof text, "%08x", hash);
  return text;
}

}  // namespace volgraph::compare

namespace volgraph::compare {
namespace {

const std::vector<std::string>& csv_metric_columns() {
  static const std::vector<std::string> names = {"rmse", "rel_rmse", "psnr", "ssim", "flip", "max_abs", "rel_mean"};
  return names;
}

// RFC 4180 §2: a field with a comma, quote or line break is quoted, its quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

// The shortest text that reads back as the same double.
std::string csv_number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return Json(value).dump();
}

// A setting's JSON text as a cell: a string's characters, other JSON as written.
std::string setting_cell(const std::string& json_text) {
  try {
    const Json value = Json::parse(json_text);
    if (value.is_string()) return value.get<std::string>();
  } catch (const Json::parse_error&) {
  }
  return json_text;
}

std::vector<std::string> setting_keys(const std::vector<PointResult>& results) {
  std::vector<std::string> keys;
  for (const PointResult& p : results) {
    for (const auto& setting : p.settings) {
      if (std::find(keys.begin(), keys.end(), setting.first) == keys.end()) keys.push_back(setting.first);
    }
  }
  return keys;
}

std::vector<std::string> devices_of(const std::vector<PointResult>& results) {
  std::vector<std::string> devices;
  for (const PointResult& p : results) {
    if (std::find(devices.begin(), devices.end(), p.device) == devices.end()) devices.push_back(p.device);
  }
  return devices;
}

Json device_summary(const std::string& device, const std::vector<PointResult>& ordered) {
  std::vector<const PointResult*> front;
  int points = 0, ok = 0;
  bool is_cpu = false;
  std::string clock;
  for (const PointResult& p : ordered) {
    if (p.device != device) continue;
    ++points;
    ok += p.ok;
    is_cpu = is_cpu || p.device_is_cpu;
    if (clock.empty() && p.ok) clock = p.timing.clock;
    if (p.pareto) front.push_back(&p);
  }
  std::stable_sort(front.begin(), front.end(), [](const PointResult* a, const PointResult* b) {
    return a->timing.frame_wall_ms.median < b->timing.frame_wall_ms.median;
  });
  Json ids = Json::array();
  for (const PointResult* p : front) ids.push_back(p->id);
  return Json{{"device", device}, {"device_is_cpu", is_cpu}, {"clock", clock}, {"points", points},
              {"ok", ok},         {"failed", points - ok},   {"pareto", ids}};
}

}  // namespace

std::vector<PointResult> in_spec_order(const SweepSpec& spec, std::vector<PointResult> results) {
  std::vector<PointResult> ordered;
  std::vector<bool> taken(results.size(), false);
  for (const SweepPoint& point : spec.points) {
    for (size_t i = 0; i < results.size(); ++i) {
      if (taken[i] || results[i].id != point.id) continue;
      taken[i] = true;
      ordered.push_back(std::move(results[i]));
    }
  }
  for (size_t i = 0; i < results.size(); ++i) {
    if (!taken[i]) ordered.push_back(std::move(results[i]));
  }
  return ordered;
}

std::string results_json(const SweepSpec& spec, const std::vector<PointResult>& ordered) {
  Json points = Json::array();
  for (const PointResult& p : ordered) points.push_back(point_json(p));
  Json devices = Json::array();
  for (const std::string& device : devices_of(ordered)) devices.push_back(device_summary(device, ordered));
  const Json out{{"spec", spec.file},
                 {"description", spec.description},
                 {"config", spec.config},
                 {"size", Json::array({spec.size.width, spec.size.height})},
                 {"runs", spec.runs},
                 {"warmup", spec.warmup},
                 {"frames", spec.frames},
                 {"backend", spec.backend},
                 {"reference", spec.reference},
                 {"metric", spec.metric},
                 {"metric_lower_is_better", metric_lower_is_better(spec.metric)},
                 {"mask", spec.mask},
                 {"spec_points", spec.points.size()},
                 {"points", points},
                 {"devices", devices}};
  return out.dump(2) + "\n";
}

std::string results_csv(const std::vector<PointResult>& ordered) {
  const std::vector<std::string> keys = setting_keys(ordered);
  std::vector<std::string> header = {"id",    "series",          "label",        "device",       "ok",
                                     "error", "frame_ms_median", "frame_ms_min", "frame_ms_max", "runs"};
  for (const std::string& m : csv_metric_columns()) header.push_back(m);
  for (const char* extra : {"nan", "inf", "pareto"}) header.push_back(extra);
  for (const std::string& key : keys) header.push_back(key);
  std::string csv;
  auto line = [&csv](const std::vector<std::string>& cells) {
    for (size_t i = 0; i < cells.size(); ++i) csv += (i ? "," : "") + csv_field(cells[i]);
    csv += "\r\n";
  };
  line(header);
  for (const PointResult& p : ordered) {
    std::vector<std::string> cells = {p.id, p.series, p.label, p.device, p.ok ? "true" : "false", p.error};
    const Spread& t = p.timing.frame_wall_ms;
    for (const std::string& figure :
         {csv_number(t.median), csv_number(t.min), csv_number(t.max), std::to_string(t.runs)}) {
      cells.push_back(p.ok ? figure : "");
    }
    for (const std::string& m : csv_metric_columns())
      cells.push_back(p.ok ? csv_number(metric_value(p.metrics, m)) : "");
    cells.push_back(p.ok ? std::to_string(p.metrics.nan_values) : "");
    cells.push_back(p.ok ? std::to_string(p.metrics.inf_values) : "");
    cells.push_back(p.pareto ? "true" : "false");
    for (const std::string& key : keys) {
      auto found = std::find_if(p.settings.begin(), p.settings.end(), [&](const auto& s) { return s.first == key; });
      cells.push_back(found == p.settings.end() ? "" : setting_cell(found->second));
    }
    line(cells);
  }
  return csv;
}

namespace {

// Three significant digits (what a table for people needs; the CSV keeps every digit).
std::string figure_text(double value) {
  if (!std::isfinite(value)) return std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", value);
  return buf;
}

// A table cell: '|' escaped, line breaks as spaces (a row is one line).
std::string markdown_cell(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  for (size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.replace(at, 1, "\\|");
  return text;
}

}  // namespace

std::string results_markdown(const SweepSpec& spec, const std::vector<PointResult>& ordered) {
  std::string md;
  for (const std::string& device : devices_of(ordered)) {
    double fastest = std::numeric_limits<double>::infinity();
    for (const PointResult& p : ordered) {
      if (p.device == device && p.ok) fastest = std::min(fastest, p.timing.frame_wall_ms.median);
    }
    md += "On " + (device.empty() ? std::string("no device") : device) +
          (device.find("llvmpipe") != std::string::npos ? " — lavapipe (CPU)" : "") + ", " + std::to_string(spec.size.width) + "x" +
          std::to_string(spec.size.height) + ", median of " + std::to_string(spec.runs) + " frames after " + std::to_string(spec.warmup) +
          " warm-up; " + spec.metric + " over " + spec.mask + " pixels against the " +
          (spec.reference == "cpu" ? std::string("CPU reference") : "reference image") + "; * on the Pareto front:\n\n";
    md += "| series | setting | frame ms | min – max | / fastest | " + spec.metric + " | flip | front |\n";
    md += "|---|---|---|---|---|---|---|---|\n";
    for (const PointResult& p : ordered) {
      if (p.device != device) continue;
      const Spread& t = p.timing.frame_wall_ms;
      if (!p.ok) {
        md += "| " + markdown_cell(p.series) + " | " + markdown_cell(p.label) + " | failed: " + markdown_cell(p.error) + " | | | | | |\n";
        continue;
      }
      md += "| " + markdown_cell(p.series) + " | " + markdown_cell(p.label) + " | " + figure_text(t.median) + " | " + figure_text(t.min) +
            " – " + figure_text(t.max) + " | " + figure_text(t.median / fastest) + " | " +
            figure_text(metric_value(p.metrics, spec.metric)) + " | " + figure_text(p.metrics.flip) + " | " + (p.pareto ? "*" : "") + " |\n";
    }
    md += "\n";
  }
  return md;
}

}  // namespace volgraph::compare
