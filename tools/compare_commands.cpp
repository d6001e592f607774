// `volgraph ab`, `volgraph sweep` and `volgraph tune`: the comparison commands, on the
// comparison tools of tools/compare/ (metrics, reports, sweep specs and results).
#include "tools/compare_commands.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "graph/rhi/vulkan/context.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/linear_output.h"
#include "tools/compare/ab_report.h"
#include "tools/compare/flip.h"
#include "tools/compare/interrupt_guard.h"
#include "tools/compare/metrics.h"
#include "tools/compare/render_setting.h"
#include "tools/compare/sweep_folder.h"
#include "tools/compare/sweep_results.h"
#include "tools/compare/sweep_spec.h"
#include "tools/compare/tune.h"
#include "tools/image_io.h"
#include "tools/output_files.h"
#include "tools/simulated_fault.h"
#include "tools/webgpu_backend.h"

namespace volgraph {
namespace {

namespace fs = std::filesystem;
using namespace compare;

// The device a comparison runs on, and the validation messages it gathered.
class ComparisonDevice {
 public:
  ComparisonDevice(const std::string& backend, int device_index, bool validation) {
    const std::optional<SimulatedFault> fault = simulated_fault();
    if (!fault) throw UsageError("VOLGRAPH_SIMULATE_FAULT must be out_of_memory or device_lost");
    if (backend == "webgpu") {
      if (device_index >= 0) throw UsageError("--device picks a Vulkan device; WebGPU uses Dawn's default adapter");
      device_ = create_webgpu_device(*fault);
      return;
    }
    context_ = vulkan::Context::create({.validation = validation, .device_index = device_index, .simulate = *fault});
    device_ = std::make_unique<vulkan::VulkanDevice>(*context_);
  }
  rhi::Device& device() { return *device_; }
  // The Khronos layer's messages since the last call (none on WebGPU: Dawn's errors throw).
  std::vector<std::string> take_validation_messages() { return context_ ? context_->take_validation_messages() : std::vector<std::string>{}; }

 private:
  std::unique_ptr<vulkan::Context> context_;
  std::unique_ptr<rhi::Device> device_;
};

// -o DIR: a folder, or a name whose parent folder exists; created (when `create`) if missing.
void prepare_output_folder(const std::string& dir, bool create = true) {
  if (dir.empty()) throw UsageError("expected -o DIR, the folder the results go to");
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw ConfigError({{{"<command line>", "-o " + dir, 0}, "exists and is not a folder; expected a folder"}});
    return;
  }
  const fs::path parent = fs::absolute(dir, ec).parent_path();
  if (!fs::is_directory(parent, ec)) {
    throw ConfigError({{{"<command line>", "-o " + dir, 0}, "its parent folder " + parent.string() + " does not exist"}});
  }
  if (create && !fs::create_directory(dir, ec)) throw IoError(dir + ": " + ec.message());
}

// --a/--b "VARIANT[,param=value…]" as overrides of pass `pass`: a first item without
// '=' is the variant; "param=value" sets pass.param, "other.param=value" another pass's.
// Commas inside brackets belong to the value ([1, 2, 3]).
void add_side_settings(const std::string& flag, const std::string& text, const std::string& pass, Overrides& overrides) {
  std::vector<std::string> items;
  std::string item;
  int depth = 0;
  for (char c : text) {
    depth += c == '[' ? 1 : c == ']' ? -1 : 0;
    if (c == ',' && depth == 0) {
      items.push_back(item);
      item.clear();
    } else {
      item += c;
    }
  }
  items.push_back(item);
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string& it = items[i];
    const size_t eq = it.find('=');
    if (it.empty()) throw UsageError(flag + " " + text + ": an empty item; expected VARIANT[,param=value…]");
    if (eq == std::string::npos) {
      if (i != 0) throw UsageError(flag + " " + text + ": \"" + it + "\" is not param=value; only the first item names a variant");
      if (pass.empty()) throw UsageError(flag + " names a variant; expected --pass NAME too");
      overrides.variants.push_back(pass + "=" + it);
      continue;
    }
    const std::string key = it.substr(0, eq);
    if (key.find('.') != std::string::npos) {
      overrides.sets.push_back(it);
      continue;
    }
    if (pass.empty()) throw UsageError(flag + " sets \"" + key + "\"; expected --pass NAME too, or PASS." + key);
    overrides.sets.push_back(pass + "." + it);
  }
}

// One side's setting in words: "fog_integral=hillaire, fog_media.slices=64", or its graph.
std::string setting_text(const Overrides& side) {
  std::string out = side.graph.empty() ? "" : "graph " + side.graph;
  for (const std::string& v : side.variants) out += (out.empty() ? "" : ", ") + v;
  for (const std::string& s : side.sets) out += (out.empty() ? "" : ", ") + s;
  return out.empty() ? "the config as it is" : out;
}

// The command that renders a side's image alone, as compared (linear, the same frames).
std::string render_command(const Args& args, const Overrides& applied, const std::string& file) {
  std::vector<std::string> words = {"volgraph", "render", args.config, "--size",
                                    std::to_string(applied.size->width) + "x" + std::to_string(applied.size->height),
                                    "--frames", std::to_string(args.frames)};
  if (args.backend != "vulkan") words.insert(words.end(), {"--backend", args.backend});
  if (!applied.graph.empty()) words.insert(words.end(), {"--graph", applied.graph});
  for (const std::string& v : applied.variants) words.insert(words.end(), {"--variant", v});
  for (const std::string& s : applied.sets) words.insert(words.end(), {"--set", s});
  words.insert(words.end(), {"-o", file});
  return shell_command(words);
}

std::string number_text(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

std::string reference_command(const Args& args, const Extent& size, const std::string& file) {
  return shell_command({"volgraph", "reference", args.config, "--size", std::to_string(size.width) + "x" + std::to_string(size.height),
                        "--tolerance", number_text(args.tolerance), "-o", file});
}

// The config's own size, or --size.
Extent size_of(const Args& args, const PassRegistry& registry) {
  if (args.overrides.size) return *args.overrides.size;
  return load_config(args.config, registry, {}).config.output_size;
}

// A side's overrides as applied: the shared ones, the side's, then the linear output.
struct Side {
  Overrides chosen;   // the shared and the side's own (what the report names)
  Overrides applied;  // with the linear output (what was rendered)
  LoadedConfig loaded;
};

Side load_side(const Args& args, const PassRegistry& registry, const std::string& flag, const std::string& settings,
               const std::string& graph, Extent size) {
  Overrides o = args.overrides;
  o.size = size;
  o.graph = graph;
  if (!settings.empty()) add_side_settings(flag, settings, args.compare.pass, o);
  LoadedConfig plain = load_config(args.config, registry, o);
  for (const Diagnostic& w : plain.warnings) std::cerr << format_warning(w) << "\n";
  Overrides applied = linear_output(plain.config, o);
  return {o, applied, load_config(args.config, registry, applied)};
}

// The figures of `test` against `against` over each mask, and the per-pixel maps.
Comparison compare_images(const std::string& test_label, const RgbImage& test, const std::string& against_label,
                          const RgbImage& against, const std::vector<std::pair<std::string, PixelMask>>& masks) {
  Comparison c{test_label, against_label, {}, abs_error_map(test, against), flip_hdr_map(test, against)};
  for (const auto& [name, mask] : masks) {
    const size_t pixels = mask.empty() ? test.pixels() : size_t(std::count(mask.begin(), mask.end(), true));
    if (pixels == 0) continue;
    c.by_mask.push_back({mask_title(name), pixels, measure_error(test, against, mask)});
  }
  return c;
}

std::string ms_text(const Spread& s) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(2) << s.median << " ms [" << s.min << "–" << s.max << "]";
  return o.str();
}

void print_ab_summary(const AbReport& report, const std::string& dir) {
  std::cout << "volgraph ab: " << report.config << " at " << report.width << "x" << report.height << " on " << report.device
            << (report.device_is_cpu ? " — lavapipe (CPU): times are CPU times" : "") << "\n";
  for (const Rendered& r : report.renders) {
    std::cout << "  " << std::left << std::setw(10) << r.label << r.setting;
    if (r.timing) std::cout << ": frame " << ms_text(r.timing->frame_wall_ms) << " over " << r.timing->runs << " runs";
    std::cout << "\n";
  }
  for (const Comparison& c : report.comparisons) {
    for (const MaskedMetrics& m : c.by_mask) {
      std::cout << "  " << c.test << " vs " << c.against << ", " << m.mask << " (" << m.mask_pixels << "): rel_rmse "
                << m.metrics.relative_rmse << ", psnr " << m.metrics.psnr_db << " dB, ssim " << m.metrics.ssim << ", flip "
                << m.metrics.flip << ", max abs " << m.metrics.max_abs_error;
      if (m.metrics.nan_values + m.metrics.inf_values) std::cout << ", " << m.metrics.nan_values << " NaN, " << m.metrics.inf_values << " Inf";
      std::cout << "\n";
    }
  }
  std::cout << "report: " << (fs::path(dir) / "report.html").string() << "\n";
}

void stage_report(const std::string& dir, const std::vector<std::pair<std::string, std::vector<std::byte>>>& files) {
  OutputFiles out;
  for (const auto& [name, bytes] : files) out.stage((fs::path(dir) / name).string(), "-o", bytes);
  out.commit();
}

std::string version_text() {
#ifdef VOLGRAPH_VERSION
  return VOLGRAPH_VERSION;
#else
  return "unknown";
#endif
}

// Every file ab writes into -o DIR (ab_report_files), for check_outputs_not_inputs.
std::vector<std::string> ab_output_names() {
  std::vector<std::string> names = {"report.json", "report.html"};
  for (const char* stem : {"a", "b", "reference"}) {
    for (const char* ext : {".png", ".pfm"}) names.push_back(std::string(stem) + ext);
  }
  for (const char* pair : {"b_vs_a", "a_vs_reference", "b_vs_reference"}) {
    for (const char* map : {"error_", "flip_"}) names.push_back(std::string(map) + pair + ".png");
  }
  return names;
}

}  // namespace

int run_ab(const Args& args, const PassRegistry& registry) {
  const CompareArgs& c = args.compare;
  if (args.config.empty()) throw UsageError("ab needs a CONFIG file");
  if (c.a.empty() && c.a_graph.empty() && c.b.empty() && c.b_graph.empty()) {
    throw UsageError("ab compares two settings; expected --a and --b (VARIANT[,param=value…]) or --a-graph and --b-graph");
  }
  if (!c.reference.empty() && c.reference != "cpu" && image_format_for(c.reference) != ImageFormat::pfm) {
    throw UsageError("--reference expects cpu or a .pfm image, got \"" + c.reference + "\"");
  }
  prepare_output_folder(args.output, false);  // created once the settings load
  check_outputs_not_inputs({{"the config", args.config}, {"--a-graph", c.a_graph}, {"--b-graph", c.b_graph}, {"--reference", c.reference}},
                           "-o", args.output, ab_output_names());
  const Extent size = size_of(args, registry);
  Side a = load_side(args, registry, "--a", c.a, c.a_graph, size);
  Side b = load_side(args, registry, "--b", c.b, c.b_graph, size);
  compile_loaded(a.loaded, args.compile);
  compile_loaded(b.loaded, args.compile);
  prepare_output_folder(args.output);

  InterruptGuard interrupt("no report written (a report is written whole or not at all)");  // a Ctrl-C while the report is written waits for it
  ComparisonDevice session(args.backend, args.device, args.validation);
  rhi::Device& device = session.device();
  const RunSettings run{args.frames, c.warmup.value_or(1), c.runs.value_or(5), args.compile};
  std::vector<SettingRun> runs = run_settings(device, {&a.loaded, &b.loaded}, run);

  AbReport report;
  report.volgraph_version = version_text();
  report.command_line = args.command_line;
  report.config = args.config;
  report.pass = c.pass;
  const rhi::AdapterInfo info = device.info();
  report.backend = info.backend;
  report.device = info.device;
  report.driver = info.driver;
  report.device_is_cpu = device_is_cpu(device);
  report.width = size.width;
  report.height = size.height;
  report.frames = args.frames;
  report.renders.push_back({"A", setting_text(a.chosen), render_command(args, a.applied, "a.pfm"),
                            runs[0].image, runs[0].timing, runs[0].memory, 0});
  report.renders.push_back({"B", setting_text(b.chosen), render_command(args, b.applied, "b.pfm"),
                            runs[1].image, runs[1].timing, runs[1].memory, 0});
  report.notes.push_back(runs[0].timing.clock);
  report.notes.push_back("Images are linear radiance: every composite pass at variant none, exposure 0. Timed rounds alternate A and B.");

  const Scene& scene = a.loaded.config.scene;
  const std::vector<std::pair<std::string, PixelMask>> masks = {
      {"all", {}}, {"fog_only", mask_named("fog_only", scene, size.width, size.height)},
      {"surfaces", mask_named("surfaces", scene, size.width, size.height)}};
  if (c.reference.empty()) {
    report.comparisons.push_back(compare_images("B", runs[1].image, "A", runs[0].image, masks));
    report.notes.push_back("No reference: B is measured against A.");
  } else {
    const auto start = std::chrono::steady_clock::now();
    const RgbImage ref = c.reference == "cpu"
                             ? render_reference(a.loaded, {unsigned(args.threads), args.tolerance, uint32_t(args.samples_per_axis), uint32_t(args.atmosphere_paths)})
                             : read_reference_image(c.reference, size.width, size.height, "--reference");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string command = c.reference == "cpu" ? reference_command(args, size, "reference.pfm") : "(the image " + c.reference + ")";
    report.renders.push_back({"reference", c.reference == "cpu" ? "CPU reference" : c.reference, command, ref, std::nullopt, std::nullopt, seconds});
    report.comparisons.push_back(compare_images("A", runs[0].image, "reference", ref, masks));
    report.comparisons.push_back(compare_images("B", runs[1].image, "reference", ref, masks));
  }
  const std::vector<std::string> messages = session.take_validation_messages();
  for (const std::string& m : messages) std::cerr << "validation: " << m << "\n";
  {
    const std::lock_guard<std::mutex> lock(interrupt.writes());
    stage_report(args.output, ab_report_files(report));
  }
  print_ab_summary(report, args.output);
  return messages.empty() ? kOk : kFailure;
}

namespace {

// The spec's reference image: its file, or the CPU reference of `base` rendered once and
// kept as DIR/reference.pfm for the points that follow (and a resumed run, and jobs).
RgbImage sweep_reference(const Args& args, const SweepSpec& spec, const LoadedConfig& base, const std::string& dir) {
  if (spec.reference != "cpu") return read_reference_image(spec.reference, spec.size.width, spec.size.height, "the reference");
  const std::string kept = (fs::path(dir) / "reference.pfm").string();
  std::error_code ec;
  if (fs::exists(kept, ec)) return read_reference_image(kept, spec.size.width, spec.size.height, "the kept reference");
  std::cerr << "sweep: rendering the CPU reference at " << spec.size.width << "x" << spec.size.height << "\n";
  const RgbImage ref = render_reference(base, {unsigned(args.threads), args.tolerance, uint32_t(args.samples_per_axis), uint32_t(args.atmosphere_paths),
                                              spec.reference_mode == "refracted"});
  write_image(kept, Image{ref.width, ref.height, rgba_from_rgb(ref)}, "-o");
  return ref;
}

// The spec's config at the spec's size, linear: the scene the reference and masks are of.
LoadedConfig sweep_base(const PassRegistry& registry, const SweepSpec& spec) {
  Overrides sized;
  sized.size = spec.size;
  return load_linear(spec.config, registry, sized);
}

// A sweep's device, reference and mask, made once and shared by its points.
class SweepRunner {
 public:
  SweepRunner(const Args& args, const PassRegistry& registry, const SweepSpec& spec, const std::string& dir)
      : args_(args), registry_(registry), spec_(spec), session_(spec.backend, args.device, args.validation) {
    const LoadedConfig base = sweep_base(registry, spec);
    reference_ = sweep_reference(args, spec, base, dir);
    mask_ = mask_named(spec.mask, base.config.scene, spec.size.width, spec.size.height);
  }

  // The point rendered, timed and measured; a failure (a device error, a validation
  // message) is the point's result, with its error, and the sweep goes on.
  PointResult operator()(const SweepPoint& point) {
    const auto start = std::chrono::steady_clock::now();
    PointResult r{point.id, point.series, point.label, point.graph, point.settings};
    const rhi::AdapterInfo info = session_.device().info();
    r.backend = info.backend;
    r.device = info.device;
    r.driver = info.driver;
    r.device_is_cpu = device_is_cpu(session_.device());
    r.metric = spec_.metric;
    r.command = job_command(args_, spec_, point.id, fs::path(args_.output).string());
    try {
      measure(point, r);
      r.ok = true;
    } catch (const std::exception& e) {
      r.error = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

  // The self-contained command that runs one point of the sweep into `dir`.
  static std::string job_command(const Args& args, const SweepSpec& spec, const std::string& id, const std::string& dir) {
    std::error_code ec;
    const std::string self = fs::read_symlink("/proc/self/exe", ec).string();
    std::vector<std::string> words = {ec ? "volgraph" : self, "sweep", fs::absolute(spec.file).string(), "--point", id, "-o",
                                      fs::absolute(dir).string()};
    if (args.validation) words.push_back("--validation");
    // The command line's overrides travel with each job: its spec is the one the folder holds.
    const CompareArgs& c = args.compare;
    if (args.overrides.size) words.insert(words.end(), {"--size", std::to_string(args.overrides.size->width) + "x" + std::to_string(args.overrides.size->height)});
    if (c.runs) words.insert(words.end(), {"--runs", std::to_string(*c.runs)});
    if (c.warmup) words.insert(words.end(), {"--warmup", std::to_string(*c.warmup)});
    if (!c.backend.empty()) words.insert(words.end(), {"--backend", c.backend});
    if (!c.reference.empty()) words.insert(words.end(), {"--reference", c.reference == "cpu" ? c.reference : fs::absolute(c.reference).string()});
    return shell_command(words);
  }

 private:
  void measure(const SweepPoint& point, PointResult& r) {
    Overrides o = point.overrides;
    o.size = spec_.size;
    o.graph = point.graph;
    const LoadedConfig loaded = load_linear(spec_.config, registry_, o);
    const SettingRun run = run_settings(session_.device(), {&loaded}, {point.frames, spec_.warmup, spec_.runs, args_.compile}).front();
    if (const std::vector<std::string> messages = session_.take_validation_messages(); !messages.empty()) {
      throw std::runtime_error("validation: " + messages.front());
    }
    r.timing = run.timing;
    r.memory = run.memory;
    r.metrics = measure_error(run.image, reference_, mask_);
  }


  const Args& args_;
  const PassRegistry& registry_;
  const SweepSpec& spec_;
  ComparisonDevice session_;
  RgbImage reference_;
  PixelMask mask_;
};

// The spec as this command runs it: --size, --runs, --warmup, --backend and --reference
// in place of the spec's (a smoke run of a shipped spec at a tiny size, say).
SweepSpec sweep_spec_for(const Args& args, const PassRegistry& registry) {
  const CompareArgs& c = args.compare;
  SweepSpec spec = read_sweep_spec(args.config, registry);
  if (args.overrides.size) spec.size = *args.overrides.size;
  if (c.runs) spec.runs = *c.runs;
  if (c.warmup) spec.warmup = *c.warmup;
  if (!c.backend.empty()) spec.backend = c.backend;
  if (!c.reference.empty()) spec.reference = c.reference;
  return spec;
}

// A merge without SPEC: the folders' spec and settings, with the spec's points (for their
// order and count) when the file named is still there to read.
SweepSpec spec_of_folders(const std::string& identity, const PassRegistry& registry) {
  SweepSpec spec = spec_of_identity(identity);
  try {
    const SweepSpec read = read_sweep_spec(spec.file, registry);
    spec.description = read.description;
    spec.points = read.points;
  } catch (const std::exception&) {  // moved or changed since: the points keep their id order
  }
  return spec;
}

// Every file a sweep, its jobs, a merge or tune writes into -o DIR is none of the spec's
// inputs (the spec, its config, its reference image, its points' graphs).
void check_sweep_outputs(const SweepSpec& spec, const std::string& dir) {
  std::vector<NamedInput> inputs = {{"the spec", spec.file}, {"the spec's config", spec.config}, {"the spec's reference", spec.reference}};
  for (const SweepPoint& p : spec.points) inputs.push_back({"the graph of point " + p.id, p.graph});
  std::vector<std::string> names = {"results.json", "results.csv", "results.md", "report.html", "pareto.svg", "pareto.png",
                                    "sweep_settings.txt", "jobs.txt", "manifest.json", "tuned.json", "tuned.txt"};
  if (spec.reference == "cpu") names.push_back("reference.pfm");  // the kept CPU reference
  check_outputs_not_inputs(inputs, "-o", dir, names, {"points"});
}

const SweepPoint& point_named(const SweepSpec& spec, const std::string& id) {
  for (const SweepPoint& p : spec.points) {
    if (p.id == id) return p;
  }
  throw UsageError("--point " + id + ": no point of " + spec.file + " has that id (see its manifest.json)");
}

// --point ID: one emitted job. Saves DIR/points/ID.json (failed points too) and leaves
// the aggregates to --merge, which the jobs of one folder would race to write.
int run_one_point(const Args& args, const PassRegistry& registry, const SweepSpec& spec) {
  const SweepPoint& point = point_named(spec, args.compare.point);
  SweepRunner runner(args, registry, spec, args.output);
  PointResult result;
  try {
    result = runner(point);
  } catch (const std::exception& e) {
    result = {point.id, point.series, point.label, point.graph, point.settings};
    result.error = e.what();
    result.metric = spec.metric;
  }
  save_point(args.output, result);
  std::cerr << "sweep: point " << point.id << " (" << point.label << "): " << (result.ok ? "done" : "FAILED: " + result.error) << "\n";
  return result.ok ? kOk : kFailure;
}

}  // namespace

int run_sweep_command(const Args& args, const PassRegistry& registry) {
  const CompareArgs& c = args.compare;
  if (!c.merge.empty()) {
    prepare_output_folder(args.output);
    std::optional<SweepSpec> spec;
    if (!args.config.empty()) spec = sweep_spec_for(args, registry);
    if (spec) check_sweep_outputs(*spec, args.output);
    // One sweep a folder: the folders (and SPEC) must agree; the merged folder is theirs.
    const std::string identity = common_sweep_identity(c.merge, args.output, spec ? &*spec : nullptr);
    if (!spec) spec = spec_of_folders(identity, registry);
    claim_sweep_folder(*spec, args.output);
    merge_results(c.merge, args.output, &*spec);
    std::cout << "sweep: merged " << c.merge.size() << " folder(s) into " << args.output << "\n";
    return kOk;
  }
  if (args.config.empty()) throw UsageError("sweep needs a SPEC file (configs/sweeps/*.json)");
  const SweepSpec spec = sweep_spec_for(args, registry);
  check_sweep_outputs(spec, args.output);
  prepare_output_folder(args.output);
  claim_sweep_folder(spec, args.output);
  if (c.emit_jobs) {
    sweep_reference(args, spec, sweep_base(registry, spec), args.output);  // DIR/reference.pfm once, for every job; no device
    write_jobs(args.output, spec, [&](const SweepPoint& p) { return SweepRunner::job_command(args, spec, p.id, args.output); });
    std::cout << "sweep: " << spec.points.size() << " jobs in " << (fs::path(args.output) / "jobs.txt").string()
              << "; run them (e.g. parallel < jobs.txt), then volgraph sweep --merge " << args.output << " -o " << args.output << "\n";
    return kOk;
  }
  if (!c.point.empty()) return run_one_point(args, registry, spec);
  InterruptGuard interrupt;  // before the device: its driver's threads inherit the blocked signals
  SweepRunner runner(args, registry, spec, args.output);
  const SweepSummary summary = run_sweep(spec, args.output, std::ref(runner), std::cerr, isatty(STDERR_FILENO), &interrupt.writes());
  std::cout << "sweep: " << summary.ran << " points run, " << summary.skipped << " already done, " << summary.failed
            << " failed; results in " << args.output << "\n";
  return summary.failed ? kFailure : kOk;
}

namespace {

// "; the closest is LABEL at E" over the points that succeeded ("" when none did).
std::string closest_text(const std::vector<PointResult>& results, const std::string& metric) {
  const PointResult* closest = nullptr;
  for (const PointResult& r : results) {
    if (r.ok && (!closest || metric_value(r.metrics, metric) < metric_value(closest->metrics, metric))) closest = &r;
  }
  if (!closest) return "";
  return "; the closest is \"" + closest->label + "\" (series " + closest->series + ") at " + number_text(metric_value(closest->metrics, metric));
}

}  // namespace

int run_tune(const Args& args, const PassRegistry& registry) {
  const CompareArgs& c = args.compare;
  if (args.config.empty()) throw UsageError("tune needs a SPEC file (configs/sweeps/*.json)");
  if (!c.max_error) throw UsageError("tune needs --max-error X, the largest error allowed");
  const SweepSpec spec = sweep_spec_for(args, registry);
  const std::string metric = c.metric.empty() ? spec.metric : c.metric;
  if (!is_metric_name(metric) || !metric_lower_is_better(metric)) {
    throw UsageError("--metric expects an error metric (lower is better: rmse, rel_rmse, flip, max_abs, rel_mean), got \"" + metric + "\"");
  }
  check_sweep_outputs(spec, args.output);
  prepare_output_folder(args.output);
  claim_sweep_folder(spec, args.output);
  if (read_results(args.output).size() < spec.points.size()) {  // runs what the folder lacks, else reads it
    InterruptGuard interrupt;
    SweepRunner runner(args, registry, spec, args.output);
    run_sweep(spec, args.output, std::ref(runner), std::cerr, isatty(STDERR_FILENO), &interrupt.writes());
  }
  const std::vector<PointResult> results = read_results(args.output);
  const std::optional<TuneChoice> choice = tune(results, metric, *c.max_error);
  if (!choice) {
    std::cerr << "volgraph tune: no point of " << spec.file << " has " << metric << " ≤ " << *c.max_error << closest_text(results, metric)
              << " (results in " << args.output << ")\n";
    return kFailure;
  }
  const std::string summary = tuned_summary_text(spec, *choice, metric, *c.max_error);
  OutputFiles out;
  const std::string overlay = tuned_overlay_json(spec, *choice, fs::absolute(args.output).string());
  if (tuned_overlay_possible(*choice)) out.stage((fs::path(args.output) / "tuned.json").string(), "-o", std::as_bytes(std::span(overlay)));
  out.stage((fs::path(args.output) / "tuned.txt").string(), "-o", std::as_bytes(std::span(summary)));
  out.commit();
  std::cout << summary;
  return kOk;
}

}  // namespace volgraph
