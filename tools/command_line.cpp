// The volgraph command line with CLI11 (see command_line.h). CLI11 never prints here:
// every error it throws, and every value an option rejects, becomes one volgraph message
// and exit 2; `--help` prints kUsage.
#include "tools/command_line.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>

#include <CLI/CLI.hpp>

namespace volgraph {

const char* const kUsage = R"(usage: volgraph COMMAND [options]

commands:
  validate CONFIG              check a config without a GPU (exit 0 valid, 2 invalid)
  plan CONFIG [--json|--dot]   the compiled plan: order, culling, lifetimes, memory, barriers;
                               --setup: set the passes up on --backend's device and say what each chose
  render CONFIG -o OUT         render to .png (sRGB 8-bit), .exr or .pfm (linear float)
  reference CONFIG -o OUT      the CPU ground truth of the config's scene (double precision, exact
                               visibility; pass parameters such as ambient or tone maps are not part
                               of the scene and are ignored): .exr or .pfm linear float, or .png
                               with linear values clamped to [0, 1] and sRGB-encoded (no tone map)
  ab CONFIG -o DIR             two settings of one config side by side in time and error (report.html):
                               --pass NAME --a VARIANT[,param=value…] --b …, or --a-graph FILE --b-graph FILE;
                               --reference cpu|IMAGE.pfm (default: B against A), --runs N (5), --warmup N (1)
  sweep SPEC -o DIR            every point of a sweep spec (configs/sweeps/): time, error, Pareto front,
                               results.csv/json, report.html; resumes in DIR; --emit-jobs (DIR/jobs.txt for
                               GNU parallel or tools/sweep_slurm.sh), --point ID (one job), --merge DIR (repeatable);
                               --size, --runs, --warmup, --backend, --reference override the spec's
  tune SPEC --max-error X -o DIR  the fastest point with its error (--metric, default the spec's) ≤ X:
                               DIR/tuned.json (a config including the swept one) and the flags
  view CONFIG                  the graph in a window (docs/viewer.md): --size WxH, --backend vulkan,
                               --device N, --validation, --frames N (then exit), --screenshot FILE.png,
                               --script FILE (control commands between frames), --no-overlay;
                               ESC quits, R reloads, F1 the overlay, WASD + right drag the camera
  passes                       the pass types with their variants, parameters and slots
  devices                      the Vulkan devices (index for --device N; lavapipe is the default)
  test                         run the whole test suite (handled by tools/volgraph)

options (plan, validate, render, ab):
  --size WxH                   frame size (overrides output.size)
  --set PASS.PARAM=VALUE       set a pass parameter (VALUE in JSON: 2, 0.5, true, [1,2,3], word)
  --variant PASS=VARIANT       swap a pass's variant
  --graph FILE                 the graph of FILE (e.g. configs/graphs/raymarch_fog.json) in place of
                               the config's: another technique on the same scene
  --no-cull                    keep every pass (debug)
  --no-alias                   give every transient resource its own memory (debug)
  --serialize                  a full barrier between every two passes (debug)

options (reference; ab, sweep and tune for their CPU reference):
  --size WxH                   frame size (overrides output.size)
  --threads N                  worker threads, at most 256 (default: the hardware's); the image does not depend on it
  --spp N                      samples per pixel on a regular sub-pixel grid, N a square (1, 4, 9, …);
                               default 1: pixel centres, as the GPU samples
  --tolerance X                relative error allowed in each stretch of the media integral (default 1e-5)
  --paths N                    Monte Carlo paths a ray for the atmosphere's scattering orders past the first
                               (default 64; 0: single scattering alone, exact to the quadrature)

options (render, ab):
  --backend vulkan|webgpu      default vulkan; webgpu: Dawn (its Vulkan backend on lavapipe here)
  --device N                   a Vulkan device by index (volgraph devices); default lavapipe (vulkan only)
  --frames N                   render N frames, write the last
  --timings                    per-pass GPU and CPU times of the last frame, JSON on stdout
                               (CPU only, said so, where the device has no time stamps)
  --timings-out FILE           the same JSON to FILE
  --validation                 run under the Khronos validation layer (synchronization too);
                               WebGPU validates always: any Dawn error fails the render (exit 1)
  --dump PASS.SLOT=FILE        also write that resource: textures as images (3D: slices stacked, slice 0 on top), buffers raw (.bin)
)";

int bad_usage(const std::string& message) {
  std::cerr << "volgraph: " << message << "\n(run 'volgraph --help' for usage)\n";
  return kBadInput;
}

namespace {

// A value option: every occurrence, in order, goes to `take`, which checks it (throwing
// UsageError) and keeps it; where one value is kept, the last one wins.
void value_option(CLI::App& app, const std::string& name, std::function<void(const std::string&)> take) {
  app.add_option(name)->each(std::move(take))->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

void flag(CLI::App& app, const std::string& name, std::function<void()> set) {
  app.add_flag_callback(name, std::move(set));
}

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

// Digits only (no sign, space or other text), at most `max`: the number, else nullopt.
std::optional<unsigned long> digits_value(const std::string& text, unsigned long max) {
  if (text.empty() || text.size() > 9 || !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); })) {
    return std::nullopt;
  }
  const unsigned long n = std::stoul(text);
  if (n > max) return std::nullopt;
  return n;
}

// WxH: two runs of digits around one x, each side in [1, 16384].
Extent size_value(const std::string& text) {
  const size_t x = text.find_first_of("xX");
  const auto w = x == std::string::npos ? std::nullopt : digits_value(text.substr(0, x), 16384);
  const auto h = x == std::string::npos ? std::nullopt : digits_value(text.substr(x + 1), 16384);
  if (!w || !h || *w < 1 || *h < 1) {
    throw UsageError("--size expects WxH, digits only, each side in [1, 16384], got " + quoted(text));
  }
  return Extent{uint32_t(*w), uint32_t(*h), 1};
}

// --frames, --device: a whole number in [low, 100000].
int whole_number(const std::string& flag_name, const std::string& text, long low) {
  const std::optional<unsigned long> n = digits_value(text, 100000);
  if (!n || long(*n) < low) {
    throw UsageError(flag_name + " expects a whole number ≥ " + std::to_string(low) + ", got " + quoted(text));
  }
  return int(*n);
}

// --threads: a whole number in [1, kMaxThreads]; --spp: in [1, 4096].
constexpr long kMaxThreads = 256;
long count_value(const std::string& flag_name, const std::string& text, long max = 4096) {
  const std::optional<unsigned long> n = digits_value(text, (unsigned long)max);
  if (!n || *n < 1) {
    throw UsageError(flag_name + " expects a whole number in [1, " + std::to_string(max) + "], got " + quoted(text));
  }
  return long(*n);
}

// --spp N, N a square: its root, the samples along each axis of a pixel.
int samples_per_axis(const std::string& text) {
  const long n = count_value("--spp", text);
  const long root = std::lround(std::sqrt(double(n)));
  if (root * root != n) throw UsageError("--spp expects a square number (1, 4, 9, 16, …), got " + quoted(text));
  return int(root);
}

// --paths N: the atmosphere's Monte Carlo paths a ray, a whole number in [0, 65536].
int path_count(const std::string& text) {
  const std::optional<unsigned long> n = digits_value(text, 65536);
  if (!n) throw UsageError("--paths expects a whole number in [0, 65536], got " + quoted(text));
  return int(*n);
}

double tolerance_value(const std::string& text) {
  char* end = nullptr;
  const double tolerance = std::strtod(text.c_str(), &end);
  if (*end || text.empty() || !(tolerance >= 1e-12 && tolerance <= 0.1)) {
    throw UsageError("--tolerance expects a number in [1e-12, 0.1], got " + quoted(text));
  }
  return tolerance;
}

std::string backend_value(const std::string& text) {
  if (text != "vulkan" && text != "webgpu") throw UsageError("--backend expects vulkan or webgpu, got " + quoted(text));
  return text;
}

}  // namespace

// An option that names one file: given twice, which one was meant is unclear.
void once(std::string& kept, const std::string& flag_name, const std::string& value) {
  if (!kept.empty()) throw UsageError(flag_name + " given twice (\"" + kept + "\" and \"" + value + "\"); expected one file");
  if (value.empty()) throw UsageError(flag_name + " expects a file name, got an empty one");
  kept = value;
}

void config_argument(CLI::App& app, Args& args) { app.add_option("config", args.config); }

void graph_options(CLI::App& app, Args& args) {
  value_option(app, "--size", [&](const std::string& v) { args.overrides.size = size_value(v); });
  value_option(app, "--set", [&](const std::string& v) { args.overrides.sets.push_back(v); });
  value_option(app, "--variant", [&](const std::string& v) { args.overrides.variants.push_back(v); });
  value_option(app, "--graph", [&](const std::string& v) { once(args.overrides.graph, "--graph", v); });
  flag(app, "--no-cull", [&] { args.compile.cull = false; });
  flag(app, "--no-alias", [&] { args.compile.alias = false; });
  flag(app, "--serialize", [&] { args.compile.serialize = true; });
}

void plan_options(CLI::App& app, Args& args) {
  flag(app, "--json", [&] { args.json = true; });
  flag(app, "--dot", [&] { args.dot = true; });
  flag(app, "--setup", [&] { args.setup = true; });
}

void output_option(CLI::App& app, Args& args) {
  value_option(app, "-o,--output", [&](const std::string& v) { once(args.output, "-o", v); });
}

void render_options(CLI::App& app, Args& args) {
  value_option(app, "--backend", [&](const std::string& v) { args.backend = backend_value(v); });
  value_option(app, "--device", [&](const std::string& v) { args.device = whole_number("--device", v, 0); });
  value_option(app, "--frames", [&](const std::string& v) { args.frames = whole_number("--frames", v, 1); });
  flag(app, "--timings", [&] { args.timings = true; });
  value_option(app, "--timings-out", [&](const std::string& v) { once(args.timings_out, "--timings-out", v); });
  flag(app, "--validation", [&] { args.validation = true; });
  value_option(app, "--dump", [&](const std::string& v) { args.dumps.push_back(v); });
}

void view_options(CLI::App& app, Args& args) {
  value_option(app, "--backend", [&](const std::string& v) { args.backend = backend_value(v); });
  value_option(app, "--device", [&](const std::string& v) { args.device = whole_number("--device", v, 0); });
  value_option(app, "--frames", [&](const std::string& v) { args.view_frames = whole_number("--frames", v, 1); });
  flag(app, "--validation", [&] { args.validation = true; });
  value_option(app, "--screenshot", [&](const std::string& v) { once(args.screenshot, "--screenshot", v); });
  value_option(app, "--script", [&](const std::string& v) { once(args.script, "--script", v); });
  flag(app, "--no-overlay", [&] { args.no_overlay = true; });
  value_option(app, "--shaders", [&](const std::string& v) { once(args.shaders, "--shaders", v); });
}

void reference_options(CLI::App& app, Args& args) {
  value_option(app, "--threads", [&](const std::string& v) { args.threads = int(count_value("--threads", v, kMaxThreads)); });
  value_option(app, "--spp", [&](const std::string& v) { args.samples_per_axis = samples_per_axis(v); });
  value_option(app, "--tolerance", [&](const std::string& v) { args.tolerance = tolerance_value(v); });
  value_option(app, "--paths", [&](const std::string& v) { args.atmosphere_paths = path_count(v); });
}

namespace {

double positive_number(const std::string& flag_name, const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !(x >= 0 && x < 1e300)) throw UsageError(flag_name + " expects a number ≥ 0, got " + quoted(text));
  return x;
}

}  // namespace

void ab_options(CLI::App& app, Args& args) {
  CompareArgs& c = args.compare;
  value_option(app, "--pass", [&](const std::string& v) { once(c.pass, "--pass", v); });
  value_option(app, "--a", [&](const std::string& v) { once(c.a, "--a", v); });
  value_option(app, "--b", [&](const std::string& v) { once(c.b, "--b", v); });
  value_option(app, "--a-graph", [&](const std::string& v) { once(c.a_graph, "--a-graph", v); });
  value_option(app, "--b-graph", [&](const std::string& v) { once(c.b_graph, "--b-graph", v); });
  value_option(app, "--reference", [&](const std::string& v) { once(c.reference, "--reference", v); });
}

void timing_options(CLI::App& app, Args& args) {
  CompareArgs& c = args.compare;
  value_option(app, "--runs", [&](const std::string& v) { c.runs = whole_number("--runs", v, 1); });
  value_option(app, "--warmup", [&](const std::string& v) { c.warmup = whole_number("--warmup", v, 0); });
}

void sweep_options(CLI::App& app, Args& args) {
  CompareArgs& c = args.compare;
  value_option(app, "--point", [&](const std::string& v) { once(c.point, "--point", v); });
  value_option(app, "--reference", [&](const std::string& v) { once(c.reference, "--reference", v); });
  flag(app, "--emit-jobs", [&] { c.emit_jobs = true; });
  value_option(app, "--merge", [&](const std::string& v) { c.merge.push_back(v); });
  value_option(app, "--size", [&](const std::string& v) { args.overrides.size = size_value(v); });
  value_option(app, "--backend", [&](const std::string& v) { c.backend = backend_value(v); });
  value_option(app, "--device", [&](const std::string& v) { args.device = whole_number("--device", v, 0); });
  flag(app, "--validation", [&] { args.validation = true; });
}

void tune_options(CLI::App& app, Args& args) {
  CompareArgs& c = args.compare;
  value_option(app, "--max-error", [&](const std::string& v) { c.max_error = positive_number("--max-error", v); });
  value_option(app, "--metric", [&](const std::string& v) { once(c.metric, "--metric", v); });
}

std::string shell_quote(const std::string& word) {
  const bool safe = !word.empty() && std::all_of(word.begin(), word.end(), [](unsigned char ch) {
    return std::isalnum(ch) || std::string_view("_-./=,:@%+").find(char(ch)) != std::string_view::npos;
  });
  if (safe) return word;
  std::string out = "'";
  for (char ch : word) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

std::string shell_command(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + shell_quote(w);
  return out;
}

void every_option(CLI::App& app, Args& args) {
  config_argument(app, args);
  graph_options(app, args);
  plan_options(app, args);
  output_option(app, args);
  render_options(app, args);
  reference_options(app, args);
}

namespace {

bool is_help(const std::string& word) { return word == "--help" || word == "-h" || word == "help"; }

const Command* find_command(std::span<const Command> commands, const std::string& name) {
  for (const Command& c : commands) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

// The words CLI11 matched to nothing: an unknown option is an error; a stray word is
// CONFIG while none was given (a CONFIG starting with '-' included), else unexpected.
void take_leftovers(const std::vector<std::string>& words, Args& args) {
  for (const std::string& word : words) {
    if (word.rfind("--", 0) == 0) throw UsageError("unknown option " + word);
    if (!args.config.empty()) throw UsageError("unexpected argument " + quoted(word));
    args.config = word;
  }
}

// CLI11's errors in volgraph's terms. A value goes missing only at the end of the line,
// so the option that lacks it is the last word.
int parse_error(const CLI::ParseError& error, const std::vector<std::string>& words) {
  if (dynamic_cast<const CLI::CallForHelp*>(&error)) {
    std::cout << kUsage;
    return kOk;
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
    return bad_usage(words.back().substr(0, words.back().find('=')) + " needs a value");
  }
  return bad_usage(error.what());
}

// One subcommand per command; none prints anything of CLI11's own.
void declare_commands(CLI::App& app, std::span<const Command> commands, Args& args) {
  app.set_help_flag();
  app.allow_extras();
  app.require_subcommand(1);  // at most one: a CONFIG named like a command stays a CONFIG
  for (const Command& command : commands) {
    CLI::App* sub = app.add_subcommand(command.name);
    sub->set_help_flag("-h,--help");
    sub->allow_extras();
    command.declare(*sub, args);
  }
}

}  // namespace

std::optional<int> parse_command_line(int argc, char** argv, std::span<const Command> commands, Args& args) {
  const std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty() || is_help(words[0])) {
    std::cout << kUsage;
    return words.empty() ? kBadInput : kOk;
  }
  if (!find_command(commands, words[0])) return bad_usage("unknown command " + quoted(words[0]));
  CLI::App app{"volgraph", "volgraph"};
  declare_commands(app, commands, args);
  try {
    app.parse(argc, argv);
    args.command = words[0];
    args.command_line = shell_command({argv, argv + argc});
    take_leftovers(app.remaining(true), args);
  } catch (const CLI::ParseError& e) {
    return parse_error(e, words);
  } catch (const UsageError& e) {
    return bad_usage(e.what());
  }
  return std::nullopt;
}

}  // namespace volgraph
