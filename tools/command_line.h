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

// What ab, sweep and tune take beyond the shared options.
struct CompareArgs {
  std::string pass;              // ab --pass NAME: the pass --a and --b set
  std::string a, b;              // ab --a/--b VARIANT[,param=value…]
  std::string a_graph, b_graph;  // ab --a-graph/--b-graph FILE
  std::string reference;         // ab/sweep --reference cpu|IMAGE.pfm ("" for ab: B against A)
  std::optional<int> runs, warmup;  // timed rounds, untimed frames before them (ab: 5 and 1; sweep: the spec's)
  std::string point;             // sweep --point ID: that point alone (an emitted job)
  bool emit_jobs = false;        // sweep --emit-jobs
  std::vector<std::string> merge;  // sweep --merge DIR, repeated
  std::optional<double> max_error;  // tune --max-error X
  std::string metric;            // tune --metric NAME ("" for the spec's)
  std::string backend;           // sweep/tune --backend ("" for the spec's)
};

struct Args {
  std::string command;
  std::string config;
  std::string output;
  bool json = false, dot = false;
  bool setup = false;  // plan --setup: the plan as an executor on the device runs it, with its setup notes
  std::string backend = "vulkan";
  int device = -1;
  int frames = 1;
  int threads = 0;             // reference: 0 for the hardware's
  int samples_per_axis = 1;    // reference: √spp
  double tolerance = 1e-5;     // reference: the media integral's relative tolerance
  int atmosphere_paths = 64;   // reference: Monte Carlo paths a ray for the atmosphere's orders ≥ 2 (0: single scattering)
  bool timings = false, validation = false;
  std::string timings_out;
  std::vector<std::string> dumps;
  std::string screenshot;  // view --screenshot FILE.png
  int view_frames = 0;     // view --frames N (0: until the window closes)
  std::string script;      // view --script FILE: control commands run between frames (docs/viewer.md)
  bool no_overlay = false; // view --no-overlay: frames and screenshots without the overlay
  std::string shaders;     // view --shaders DIR: the shader sources hot-reloaded ("": the build's shaders/)
  CompileOptions compile;
  Overrides overrides;
  CompareArgs compare;
  std::string command_line;  // the words as given, shell-quoted (for the reports)
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
void reference_options(CLI::App& app, Args& args);  // --threads --spp --tolerance --paths
void ab_options(CLI::App& app, Args& args);         // --pass --a --b --a-graph --b-graph --reference
void timing_options(CLI::App& app, Args& args);     // --runs --warmup
void sweep_options(CLI::App& app, Args& args);      // --point --reference --emit-jobs --merge --size --backend --device --validation
void tune_options(CLI::App& app, Args& args);       // --max-error --metric
void view_options(CLI::App& app, Args& args);       // --backend --device --frames --validation --screenshot --script --no-overlay
// All of the above but the comparison groups: what the commands older than CLI11 accept (each ignores those it
// does not use, as it always did).
void every_option(CLI::App& app, Args& args);

struct Command {
  const char* name;
  void (*declare)(CLI::App& app, Args& args);
  int (*run)(const Args& args, const PassRegistry& registry);
};

// `word` as a POSIX shell reads it back: unchanged when it is made of safe characters,
// else in single quotes.
std::string shell_quote(const std::string& word);
std::string shell_command(const std::vector<std::string>& words);

// Parses the command line into `args` (args.command: the command's name). Returns the
// exit code when the process stops here: the usage printed (0; 2 for no arguments) or a
// bad command line reported (2).
std::optional<int> parse_command_line(int argc, char** argv, std::span<const Command> commands, Args& args);

}  // namespace volgraph
