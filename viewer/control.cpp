#include "viewer/control.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "graph/diagnostics.h"

namespace volgraph::viewer {
namespace {

// Replaces the override that starts with `key` (one per pass, or per pass and parameter).
void replace_override(std::vector<std::string>& list, const std::string& key, const std::string& value) {
  std::erase_if(list, [&](const std::string& s) { return s.rfind(key, 0) == 0; });
  list.push_back(key + value);
}

std::filesystem::file_time_type mtime(const std::filesystem::path& file, uintmax_t& size) {
  std::error_code ec;
  const auto t = std::filesystem::last_write_time(file, ec);
  size = std::filesystem::file_size(file, ec);
  if (ec) size = uintmax_t(-1);
  return t;
}

}  // namespace

GraphSource::GraphSource(std::string path, const PassRegistry& registry, Overrides overrides, CompileOptions compile, LoadedConfig first)
    : path_(std::move(path)), registry_(registry), overrides_(std::move(overrides)), compile_(compile), current_(std::move(first)) {
  overrides_.size.reset();  // loaded at its own size; the loop resizes to the window
  stamps_ = stamp();
}

std::string GraphSource::set_variant(const std::string& pass, const std::string& variant) {
  Overrides next = overrides_;
  replace_override(next.variants, pass + "=", variant);
  return apply(next);
}

std::string GraphSource::set_param(const std::string& pass, const std::string& name, const std::string& json) {
  Overrides next = overrides_;
  replace_override(next.sets, pass + "." + name + "=", json);
  return apply(next);
}

std::string GraphSource::toggle_ab(const std::string& pass, const std::string& a, const std::string& b) {
  return set_variant(pass, variant_of(pass) == a ? b : a);
}

std::string GraphSource::reload() { return apply(overrides_); }

std::string GraphSource::variant_of(const std::string& pass) const {
  for (const PassNode& p : current_.config.passes) {
    if (p.name == pass) return p.variant;
  }
  return "";
}

// The whole load as `render` does it (load_config, then compile_loaded): a change that
// loads but cannot compile is refused too, so the running graph is always a good one.
std::string GraphSource::apply(const Overrides& next) {
  try {
    LoadedConfig loaded = load_config(path_, registry_, next);
    compile_loaded(loaded, compile_);
    for (const Diagnostic& w : loaded.warnings) std::cerr << format_warning(w) << "\n";
    current_ = std::move(loaded);
    overrides_ = next;
    stamps_ = stamp();
    return "";
  } catch (const ConfigError& e) {
    stamps_ = stamp();  // the bad edit is reported once, not at every poll
    return e.what();
  }
}

std::vector<GraphSource::Stamp> GraphSource::stamp() const {
  std::vector<std::string> files = current_.config.files;
  if (files.empty()) files.push_back(path_);
  std::vector<Stamp> out;
  for (const std::string& f : files) {
    Stamp s{f, {}, 0};
    s.time = mtime(f, s.size);
    out.push_back(s);
  }
  return out;
}

bool GraphSource::files_changed() const {
  for (const Stamp& s : stamps_) {
    uintmax_t size = 0;
    const auto t = mtime(s.file, size);
    if (t != s.time || size != s.size) return true;
  }
  return false;
}

namespace {

[[noreturn]] void script_error(const std::string& path, int line, const std::string& message) {
  throw ConfigError({{{path, "", line}, message}});
}

// How many words each verb takes (param: at least three, the JSON value may hold spaces).
size_t words_for(const std::string& verb) {
  if (verb == "frames" || verb == "screenshot" || verb == "capture" || verb == "show" || verb == "exposure" || verb == "slice") return 1;
  if (verb == "variant") return 2;
  if (verb == "param" || verb == "ab") return 3;
  if (verb == "reload") return 0;
  if (verb == "wait-change") return 0;
  if (verb == "camera") return 6;
  if (verb == "sun") return 2;
  return size_t(-1);
}

ScriptCommand parse_line(const std::string& path, int number, const std::string& text) {
  std::istringstream in(text);
  ScriptCommand c;
  c.line = number;
  in >> c.verb;
  const size_t expected = words_for(c.verb);
  if (expected == size_t(-1)) {
    script_error(path, number, "unknown command \"" + c.verb + "\"; expected frames, variant, param, ab, reload, screenshot, capture, show, exposure, slice, wait-change, camera or sun");
  }
  std::string word;
  for (size_t i = 0; i < (c.verb == "param" ? 2 : expected) && in >> word; ++i) c.args.push_back(word);
  if (c.verb == "param") {
    std::getline(in, word);
    const size_t first = word.find_first_not_of(" \t");
    if (first != std::string::npos) c.args.push_back(word.substr(first));
  } else if (in >> word) {
    c.args.push_back(word);
  }
  if (c.args.size() != expected) {
    script_error(path, number, c.verb + " takes " + std::to_string(expected) + " word(s): frames N | variant PASS VARIANT | param PASS NAME JSON | ab PASS A B | reload | screenshot FILE.png | capture PREFIX | show PASS.SLOT | exposure EV | slice N | wait-change | camera X Y Z TX TY TZ | sun AZ EL");
  }
  if (c.verb == "frames") {
    const std::string& n = c.args[0];
    if (n.empty() || n.size() > 6 || n.find_first_not_of("0123456789") != std::string::npos || std::stoi(n) < 1) {
      script_error(path, number, "frames " + n + ": expected a whole number from 1 to 999999");
    }
  }
  if (c.verb == "exposure" || c.verb == "slice") {
    char* end = nullptr;
    const double v = std::strtod(c.args[0].c_str(), &end);
    if (end == c.args[0].c_str() || *end != '\0' || !std::isfinite(v) || (c.verb == "slice" && (v < 0 || v != std::floor(v) || v > 1e6))) {
      script_error(path, number, c.verb + " " + c.args[0] + (c.verb == "slice" ? ": expected a whole number from 0" : ": expected a number"));
    }
  }
  if (c.verb == "camera" || c.verb == "sun") {
    for (const std::string& w : c.args) {
      char* end = nullptr;
      const double v = std::strtod(w.c_str(), &end);
      if (end == w.c_str() || *end != '\0' || !std::isfinite(v)) script_error(path, number, c.verb + " " + w + ": expected a number");
    }
  }
  if (c.verb == "screenshot" && std::filesystem::path(c.args[0]).extension() != ".png") {
    script_error(path, number, "screenshot " + c.args[0] + ": expected a .png file name");
  }
  return c;
}

}  // namespace

std::vector<ScriptCommand> read_script(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError({{{path, "", 0}, "cannot read the --script file"}});
  std::vector<ScriptCommand> out;
  std::string text;
  for (int number = 1; std::getline(in, text); ++number) {
    const size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;  // blank lines and comments
    out.push_back(parse_line(path, number, text));
  }
  return out;
}

}  // namespace volgraph::viewer
