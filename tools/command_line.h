// The volgraph command line (DESIGN.md "Command line"), parsed with CLI11: the arguments
// the commands share, the option groups a command declares, and the parser, which turns
// every bad command line into one message on stderr and exit 2.
//
// A command is a row of a Command table: its name, a function that declares its options
// on a CLI::App (from the groups below, and its own), and a function that runs it.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "graph/config/config.h"

namespace CLI {
class App;
}

namespace volgraph {

constexpr int kOk = 0, kFailure = 1, kBadInput = 2;

// What `volgraph --help` prints.
extern const char* const kUsage;

struct Args {
  std::string command;
  std::string config;
  std::string output;
  bool json = false, dot = false;
  std::string backend = "vulkan";
  int device = -1;
  int frames = 1;
  int threads = 0;             // reference: 0 for the hardware's
  int samples_per_axis = 1;    // reference: √spp
  double tolerance = 1e-5;     // reference: the media integral's relative tolerance
  bool timings = false, validation = false;
  std::string timings_out;
  std::vector<std::string> dumps;
  CompileOptions compile;
  Overrides overrides;
};

// A bad command line; a command may throw it too. Reported by bad_usage, exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "volgraph: MESSAGE" and where to find the usage, on stderr; returns kBadInput.
int bad_usage(const std::string& message);

// Option groups: each declares its options on `app`, writing into `args`.
void config_argument(CLI::App& app, Args& args);    // CONFIG
void graph_options(CLI::App& app, Args& args);      // --size --set --variant --no-cull --no-alias --serialize
void plan_options(CLI::App& app, Args& args);       // --json --dot
void output_option(CLI::App& app, Args& args);      // -o/--output OUT
void render_options(CLI::App& app, Args& args);     // --backend --device --frames --timings --timings-out
                                                    // --validation --dump
void reference_options(CLI::App& app, Args& args);  // --threads --spp --tolerance
// All of the above: what the commands older than CLI11 accept (each ignores those it
// does not use, as it always did).
void every_option(CLI::App& app, Args& args);

struct Command {
  const char* name;
  void (*declare)(CLI::App& app, Args& args);
  int (*run)(const Args& args, const PassRegistry& registry);
};

// Parses the command line into `args` (args.command: the command's name). Returns the
// exit code when the process stops here: the usage printed (0; 2 for no arguments) or a
// bad command line reported (2).
std::optional<int> parse_command_line(int argc, char** argv, std::span<const Command> commands, Args& args);

}  // namespace volgraph
