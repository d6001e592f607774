// The viewer's control: the config as loaded with the viewer's changes on top, the files
// it watches for hot reload, and the --script commands (docs/viewer.md "Control").
// Nothing here touches GLFW or Vulkan: the loop (viewer.cpp) calls it from keys and scripts.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "graph/config/config.h"

namespace volgraph::viewer {

// The config file, reloaded through the loader with the viewer's overrides on top of the
// command line's: every change is checked as `render --variant/--set` checks it, and a
// refused change leaves the last good graph (current()) as it was.
class GraphSource {
 public:
  GraphSource(std::string path, const PassRegistry& registry, Overrides overrides, CompileOptions compile, LoadedConfig first);

  LoadedConfig& current() { return current_; }
  // The command line's overrides with the viewer's changes on top (what current() was loaded with).
  const Overrides& overrides() const { return overrides_; }
  // Each returns "" when the graph changed, or the loader's message when it was refused.
  std::string set_variant(const std::string& pass, const std::string& variant);
  std::string set_param(const std::string& pass, const std::string& name, const std::string& json);
  // The pass's variant becomes `b` when it is `a`, else `a`.
  std::string toggle_ab(const std::string& pass, const std::string& a, const std::string& b);
  std::string reload();
  // The config or one of its includes changed on disk (mtime or size) since the last load.
  bool files_changed() const;
  // The pass's variant as configured ("" for the type's default; "" when no such pass).
  std::string variant_of(const std::string& pass) const;

 private:
  struct Stamp {
    std::filesystem::path file;
    std::filesystem::file_time_type time;
    uintmax_t size = 0;
  };
  std::string apply(const Overrides& next);
  std::vector<Stamp> stamp() const;

  std::string path_;
  const PassRegistry& registry_;
  Overrides overrides_;
  CompileOptions compile_;
  LoadedConfig current_;
  std::vector<Stamp> stamps_;
};

// One line of a --script file: a verb and its words.
struct ScriptCommand {
  std::string verb;               // frames, variant, param, reload, ab, screenshot, capture, show, exposure, slice, wait-change, camera, sun
  std::vector<std::string> args;  // param: PASS NAME JSON (the JSON is the rest of the line)
  int line = 0;
};

// Reads and checks a --script file before any window opens. Throws ConfigError naming
// the file and line (exit 2).
std::vector<ScriptCommand> read_script(const std::string& path);

}  // namespace volgraph::viewer
