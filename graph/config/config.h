// A loaded config: the scene, the frame size and the wired passes, each with where
// it came from so that later errors can point at the user's text.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "graph/diagnostics.h"
#include "graph/graph.h"
#include "graph/plan.h"
#include "graph/registry.h"
#include "graph/scene/scene.h"

namespace volgraph {

struct ParamSetting {
  std::string name;
  ParamValue value;
  Where where;
};

struct InputWiring {
  std::string slot;
  std::string source;  // "pass.slot"
  Where where;
};

struct OutputOverride {
  std::string slot;
  std::optional<Format> format;
  std::optional<SizeSpec> size;
  Where where;
};

struct PassNode {
  std::string name;
  std::string type;
  std::string variant;  // "" for the type's default
  std::vector<ParamSetting> params;
  std::vector<InputWiring> inputs;
  std::vector<OutputOverride> outputs;
  Where where, type_where, variant_where;
};

struct GraphOutput {
  std::string source;  // "pass.slot"
  Where where;
};

struct Config {
  std::string file;
  std::vector<std::string> files;  // every file read, the config then its includes: what a viewer watches for changes
  std::string description;
  Extent output_size{1280, 720, 1};
  Scene scene;
  std::vector<PassNode> passes;
  std::vector<GraphOutput> outputs;
};

// Command-line changes applied on top of the file (DESIGN.md: --size, --set, --variant).
struct Overrides {
  std::optional<Extent> size;
  std::vector<std::string> sets;      // "PASS.PARAM=VALUE", VALUE in JSON syntax
  std::vector<std::string> variants;  // "PASS=VARIANT"
  std::string graph;                  // --graph FILE: FILE's graph in place of the config's ("" keeps it)
};

// A config and the graph it wires, with each pass's parameter values resolved
// (indexed as the pass decl's params).
struct LoadedConfig {
  Config config;
  Graph graph;
  std::vector<std::vector<ParamValue>> params;  // per graph pass
  std::vector<Diagnostic> warnings;             // what loads but is not drawn as asked (format_warning)
};

// Reads, checks and wires a config. Throws ConfigError with every diagnostic found.
LoadedConfig load_config(const std::string& path, const PassRegistry& registry, const Overrides& overrides = {});
// The same from text already in memory (`name` is used in diagnostics and to resolve includes).
LoadedConfig load_config_text(const std::string& name, const std::string& text, const PassRegistry& registry,
                              const Overrides& overrides = {});

// compile() with a graph error (a cycle through write-after-read order) reported
// against the config as a ConfigError.
Plan compile_loaded(const LoadedConfig& loaded, const CompileOptions& options = {},
                    const RequirementsFn& requirements = {});

}  // namespace volgraph
