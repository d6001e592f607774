// `volgraph tune` (tune.h): the fastest point under an error budget, as an overlay
// config and as flags.
#include "tools/compare/tune.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace volgraph::compare {
namespace {

using Json = nlohmann::ordered_json;

std::string figure(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// The error tune compares with the budget: +inf for an image with non-finite values
// (a point that leaks NaN or Inf is never the answer) and for a NaN figure.
double error_of(const PointResult& r, const std::string& metric) {
  if (r.metrics.nan_values > 0 || r.metrics.inf_values > 0) return INFINITY;
  const double e = metric_value(r.metrics, metric);
  return std::isnan(e) ? INFINITY : e;
}

double median_ms(const PointResult& r) { return r.timing.frame_wall_ms.median; }

// A setting's JSON text back as a value (a text that is not JSON is a bare string, as --set takes it).
Json value_of(const std::string& text) {
  Json v = Json::parse(text, nullptr, false);
  return v.is_discarded() ? Json(text) : v;
}

// The setting of a point's frame count (sweep_spec.h), a flag and no pass's.
bool is_frames_key(const std::string& key) { return key == "frames"; }
bool is_variant_key(const std::string& key) { return !is_frames_key(key) && key.find('.') == std::string::npos; }

// `text` as one shell word: as it is when only safe characters, else in single quotes.
std::string shell_word(const std::string& text) {
  const bool safe = !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isalnum(c) || std::string_view("_./=:,+-@%").find(char(c)) != std::string_view::npos;
  });
  if (safe) return text;
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// --set's VALUE: a string bare when the loader reads it back as that string (it is not JSON text).
std::string set_value_text(const std::string& json_text) {
  const Json v = value_of(json_text);
  if (v.is_string() && Json::parse(v.get<std::string>(), nullptr, false).is_discarded()) return v.get<std::string>();
  return v.dump();
}

std::vector<std::string> flags_of(const PointResult& r) {
  std::vector<std::string> flags;
  if (!r.graph.empty()) flags.push_back("--graph " + shell_word(r.graph));
  for (const auto& [key, text] : r.settings) {
    if (is_frames_key(key)) {
      flags.push_back("--frames " + shell_word(set_value_text(text)));
    } else if (is_variant_key(key)) {
      const Json v = value_of(text);
      flags.push_back("--variant " + shell_word(key + "=" + (v.is_string() ? v.get<std::string>() : v.dump())));
    } else {
      flags.push_back("--set " + shell_word(key + "=" + set_value_text(text)));
    }
  }
  return flags;
}

std::string time_text(const PointResult& r) {
  const Spread& t = r.timing.frame_wall_ms;
  return figure(t.median) + " ms median [" + figure(t.min) + "–" + figure(t.max) + " ms] over " + std::to_string(t.runs) +
         " runs";
}

std::string error_text(const PointResult& r, const std::string& metric) {
  if (r.metrics.nan_values > 0 || r.metrics.inf_values > 0) {
    return std::to_string(r.metrics.nan_values) + " NaN and " + std::to_string(r.metrics.inf_values) + " Inf values";
  }
  return metric + " " + figure(metric_value(r.metrics, metric));
}

std::string device_text(const PointResult& r) { return r.device.empty() ? "an unnamed device" : r.device; }

// A point of another graph: a document that says how to render it and that the loader
// refuses (its key "render_with" is no config's), so that it never renders the config's
// own graph in the point's place.
std::string not_an_overlay_json(const SweepSpec& spec, const TuneChoice& choice) {
  const PointResult& r = choice.chosen;
  std::string command = "volgraph render " + shell_word(spec.config);
  for (const std::string& flag : flags_of(r)) command += " " + flag;
  Json doc;
  doc["description"] = "Not a config: point \"" + r.label + "\" (series \"" + r.series + "\", id " + r.id + ") of " + spec.file +
                       " renders the graph " + r.graph + ", which a config including " + spec.config +
                       " cannot swap in (a config cannot drop the graph it includes). Render it with the command of "
                       "\"render_with\"; tuned by volgraph tune: " + choice.metric + " ≤ " + figure(choice.max_error) + ", " +
                       error_text(r, choice.metric.empty() ? r.metric : choice.metric) + ", " + time_text(r) + " on " +
                       device_text(r);
  doc["render_with"] = command;
  return doc.dump(2) + "\n";
}

}  // namespace

std::optional<TuneChoice> tune(const std::vector<PointResult>& results, const std::string& metric, double max_error) {
  if (!is_metric_name(metric)) throw std::invalid_argument("no metric named \"" + metric + "\"; expected " + one_of(metric_names()));
  if (!metric_lower_is_better(metric)) {
    throw std::invalid_argument("tune needs an error, lower is better; \"" + metric + "\" is higher-is-better");
  }
  if (std::isnan(max_error)) throw std::invalid_argument("the error budget is NaN");
  const auto first_ok = std::find_if(results.begin(), results.end(), [](const PointResult& r) { return r.ok; });
  if (first_ok == results.end()) return std::nullopt;
  const std::string device = first_ok->device;

  TuneChoice choice;
  choice.metric = metric;
  choice.max_error = max_error;
  std::vector<const PointResult*> over;
  const PointResult* best = nullptr;
  for (const PointResult& r : results) {
    if (!r.ok) continue;
    if (r.device != device) {
      if (std::find(choice.other_devices.begin(), choice.other_devices.end(), r.device) == choice.other_devices.end()) {
        choice.other_devices.push_back(r.device);
      }
      continue;
    }
    ++choice.points;
    if (error_of(r, metric) > max_error) {
      over.push_back(&r);
      continue;
    }
    ++choice.candidates;
    if (!best || median_ms(r) < median_ms(*best)) best = &r;
  }
  if (!best) return std::nullopt;
  choice.chosen = *best;
  std::stable_sort(over.begin(), over.end(), [](const PointResult* a, const PointResult* b) { return median_ms(*a) < median_ms(*b); });
  for (const PointResult* r : over) {
    if (median_ms(*r) < median_ms(*best)) choice.faster_over_budget.push_back(*r);
  }
  return choice;
}

bool tuned_overlay_possible(const TuneChoice& choice) { return choice.chosen.graph.empty(); }

std::string tuned_overlay_json(const SweepSpec& spec, const TuneChoice& choice, const std::string& overlay_dir) {
  const PointResult& r = choice.chosen;
  if (!tuned_overlay_possible(choice)) return not_an_overlay_json(spec, choice);
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path config = fs::weakly_canonical(fs::absolute(spec.config), ec);
  const fs::path dir = fs::weakly_canonical(fs::absolute(overlay_dir.empty() ? "." : overlay_dir), ec);
  fs::path include = config.lexically_relative(dir);
  if (include.empty()) include = config;

  Json passes = Json::array();
  auto entry = [&](const std::string& pass) -> Json& {
    for (Json& p : passes) {
      if (p["name"] == pass) return p;
    }
    passes.push_back(Json{{"name", pass}});
    return passes.back();
  };
  std::string frames_note;
  for (const auto& [key, text] : r.settings) {
    if (is_frames_key(key)) {
      frames_note = "; render it with --frames " + set_value_text(text) + " (a config holds no frame count)";
      continue;
    }
    if (is_variant_key(key)) {
      entry(key)["variant"] = value_of(text);
      continue;
    }
    const size_t dot = key.find('.');
    entry(key.substr(0, dot))["params"][key.substr(dot + 1)] = value_of(text);
  }
  const std::string metric = !choice.metric.empty() ? choice.metric : !r.metric.empty() ? r.metric : spec.metric;
  Json overlay;
  overlay["description"] = "Point \"" + r.label + "\" (series \"" + r.series + "\", id " + r.id + ") of " + spec.file +
                           ", tuned by volgraph tune: " + metric + " ≤ " + figure(choice.max_error) + ", " +
                           error_text(r, metric) + ", " + time_text(r) + " on " + device_text(r) + " (" +
                           std::to_string(choice.candidates) + " of " + std::to_string(choice.points) +
                           " points under the budget)" + frames_note;
  overlay["include"] = include.generic_string();
  // One pass a line, the way the shipped configs are written.
  std::string out = "{\n  \"description\": " + overlay["description"].dump() + ",\n  \"include\": " + overlay["include"].dump() +
                    ",\n  \"graph\": { \"passes\": [\n";
  for (size_t i = 0; i < passes.size(); ++i) out += "    " + passes[i].dump() + (i + 1 < passes.size() ? ",\n" : "\n");
  return out + "  ] }\n}\n";
}

std::string tuned_summary_text(const SweepSpec& spec, const TuneChoice& choice, const std::string& metric, double max_error) {
  const PointResult& r = choice.chosen;
  std::string out;
  for (const std::string& flag : flags_of(r)) out += flag + "\n";
  out += "chosen: \"" + r.label + "\" (series \"" + r.series + "\", id " + r.id + ") of " + spec.file + ": " + time_text(r) +
         ", " + error_text(r, metric) + " ≤ " + figure(max_error) + ", on " + device_text(r) + "\n";
  out += "  " + std::to_string(choice.candidates) + " of " + std::to_string(choice.points) + " points under the budget\n";
  if (!choice.other_devices.empty()) {
    out += "  tuned over the first result's device only; left out:";
    for (const std::string& d : choice.other_devices) out += " \"" + d + "\"";
    out += "\n";
  }
  if (!tuned_overlay_possible(choice)) {
    out += "  no overlay: the series renders its own graph (" + r.graph +
           "), which a config including " + spec.config + " cannot swap in; render with the flags above\n";
  }
  if (choice.faster_over_budget.empty()) {
    out += "no faster point\n";
    return out;
  }
  out += "faster, over the budget:\n";
  for (const PointResult& f : choice.faster_over_budget) {
    out += "  " + figure(median_ms(f)) + " ms  " + error_text(f, metric) + " > " + figure(max_error) + "  \"" + f.label +
           "\" (series \"" + f.series + "\")\n";
  }
  return out;
}

}  // namespace volgraph::compare
