// The volgraph command line (DESIGN.md "Command line"): the commands, parsed by
// tools/command_line.h (CLI11). Exit codes: 0 success, 1 failure that is not the input's
// fault, 2 bad input (one clear message each).
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <span>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <unistd.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "tools/command_line.h"
#include "tools/compare_commands.h"
#include "tools/image_io.h"
#include "tools/output_files.h"
#include "tools/simulated_fault.h"
#include "tools/webgpu_backend.h"
#include "graph/plan_report.h"
#include "graph/probe.h"
#include "graph/pooling.h"
#include "graph/rhi/device_error.h"
#include "graph/rhi/vulkan/context.h"
#include "passes/passes.h"
#include "reference/image_render.h"
#include "reference/media.h"
#include "reference/atmosphere_reference.h"
#include "reference/clouds.h"
#include "reference/renderer.h"
#include "viewer/viewer.h"

namespace volgraph {
namespace {

std::string range_text(const ParamDecl& p) {
  if (p.type == ParamType::choice) {
    std::string out;
    for (const std::string& c : p.choices) out += (out.empty() ? "" : "|") + c;
    return out;
  }
  if (p.type == ParamType::boolean) return "true|false";
  return "[" + param_value_text(p.min) + ", " + param_value_text(p.max) + "]";
}

// A slot's size as `volgraph passes` shows it, its parameters by name ("resolution²").
std::string size_text(const PassDecl& decl, const SlotDecl& s) {
  if (!s.like.empty()) return "like " + s.like;
  if (s.kind == ResourceKind::buffer) return std::to_string(s.size.buffer_bytes) + " B";
  auto name = [&](const SizeSpec::ParamIndex& p) { return decl.params.at(*p).name; };
  std::string out;
  switch (s.size.mode) {
    case SizeSpec::Mode::absolute:
      out = std::to_string(s.size.absolute.width) + "x" + std::to_string(s.size.absolute.height);
      break;
    case SizeSpec::Mode::relative:
      out = s.size.scale_x == 1.0f && s.size.scale_y == 1.0f ? "frame" : "frame × " + param_value_text(double(s.size.scale_x));
      if (s.size.divisor_param) out += " / " + name(s.size.divisor_param);
      break;
    case SizeSpec::Mode::square_param:
      if (s.size.height_param) out = name(s.size.param) + " × " + name(s.size.height_param);
      else out = s.size.fixed_height ? name(s.size.param) + " × " + std::to_string(s.size.fixed_height) : name(s.size.param) + "²";
      break;
  }
  if (s.kind != ResourceKind::texture3d) return out;
  std::string depth = std::to_string(s.size.absolute.depth);
  if (s.size.mode == SizeSpec::Mode::relative && s.size.param) depth = name(s.size.param);
  if (s.size.mode == SizeSpec::Mode::square_param && s.size.depth_param) depth = name(s.size.depth_param);
  return out + " × " + depth;
}

int print_passes(const PassRegistry& registry) {
  for (const auto& d : registry.all()) {
    std::cout << d->name << " (" << pass_kind_name(d->kind) << "): " << d->doc << "\n  variants:";
    for (const VariantDecl& v : d->variants) std::cout << " " << v.name;
    std::cout << "\n";
    for (const ParamDecl& p : d->params) {
      std::cout << "  param " << p.name << ": " << param_type_name(p.type) << " " << range_text(p)
                << (p.unit.empty() ? "" : " " + p.unit) << ", default " << param_value_text(p.default_value) << " — "
                << p.doc << "\n";
    }
    for (const SlotDecl& s : d->slots) {
      const char* dir = s.direction == SlotDirection::input    ? "in"
                        : s.direction == SlotDirection::output  ? "out"
                        : s.direction == SlotDirection::history ? "history"
                                                                : "inout";
      std::cout << "  " << dir << " " << s.name << ": ";
      if (s.direction == SlotDirection::history) std::cout << "last frame of output " << s.history_of << ", " << usage_name(s.usage);
      else std::cout << kind_name(s.kind) << ", " << usage_name(s.usage);
      if (s.direction == SlotDirection::output) {
        if (s.kind != ResourceKind::buffer && s.like.empty()) std::cout << ", " << format_info(s.format).name;
        std::cout << ", " << size_text(*d, s);
      } else if (s.format != Format::undefined) {
        std::cout << ", " << format_info(s.format).name;
      }
      if (s.optional) std::cout << ", optional";
      if (s.persistent) std::cout << ", persistent";
      if (s.format_overridable) std::cout << ", format overridable";
      if (s.size_overridable) std::cout << ", size overridable";
      std::cout << " — " << s.doc << "\n";
    }
    if (d->needs) {
      std::cout << "  needs:";
      for (uint32_t f = 0; f < uint32_t(SceneFeature::count); ++f) {
        if (d->needs & (1u << f)) std::cout << " " << feature_name(SceneFeature(f));
      }
      std::cout << "\n";
    }
    if (d->needs_any) std::cout << "  needs: " << features_or_text(d->needs_any) << "\n";
  }
  return kOk;
}

int print_devices() {
  const auto devices = vulkan::Context::list_devices();
  if (devices.empty()) std::cout << "no Vulkan devices\n";
  for (size_t i = 0; i < devices.size(); ++i) {
    const auto& d = devices[i];
    std::cout << i << ": " << d.name << " — " << d.driver << ", Vulkan " << VK_API_VERSION_MAJOR(d.api_version) << "."
              << VK_API_VERSION_MINOR(d.api_version) << "." << VK_API_VERSION_PATCH(d.api_version)
              << "; dual-source blending (dualSrcBlend): " << (d.dual_source_blending ? "offered" : "not offered") << "\n";
  }
  try {
    std::cout << describe_webgpu_adapter() << "\n";
  } catch (const DeviceError& e) {
    std::cout << "webgpu: " << e.what() << "\n";
  }
  return kOk;
}

std::string timings_json(const std::vector<PassTiming>& timings, const rhi::Device& device, int frames,
                         double frame_wall_ms) {
  const rhi::AdapterInfo adapter = device.info();
  std::ostringstream o;
  o << "{\n  \"device\": \"" << adapter.device << "\",\n  \"backend\": \"" << adapter.backend
    << "\",\n  \"frames\": " << frames << ",\n  \"gpu_timestamps\": " << (device.has_timestamps() ? "true" : "false")
    << ",\n";
  if (!device.has_timestamps()) {
    o << "  \"timing\": \"cpu: the adapter has no time stamps, so gpu_ms are 0; cpu_ms and frame_wall_ms are measured\",\n";
  }
  if (adapter.device.find("llvmpipe") != std::string::npos) {
    o << "  \"note\": \"lavapipe (CPU): the GPU is the CPU; its time stamps do not bracket compute dispatches "
         "reliably, frame_wall_ms (submit to completion) does\",\n";
  }
  o << "  \"passes\": [\n";
  double gpu = 0, cpu = 0;
  for (size_t i = 0; i < timings.size(); ++i) {
    const PassTiming& t = timings[i];
    gpu += t.gpu_ms;
    cpu += t.cpu_ms;
    o << "    {\"pass\": \"" << t.pass << "\", \"type\": \"" << t.type << "\", \"gpu_ms\": " << t.gpu_ms
      << ", \"cpu_ms\": " << t.cpu_ms << ", \"cached\": " << (t.cached ? "true" : "false") << "}"
      << (i + 1 < timings.size() ? "," : "") << "\n";
  }
  o << "  ],\n  \"total_gpu_ms\": " << gpu << ",\n  \"total_cpu_ms\": " << cpu << ",\n  \"frame_wall_ms\": "
    << frame_wall_ms << "\n}\n";
  return o.str();
}

// The host ran out of memory allocating what the message names: not the input's fault
// (exit 1), said in the user's terms rather than as std::bad_alloc.
struct OutOfHostMemory : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Dump {
  uint32_t resource;
  std::string file;
};

std::vector<Dump> add_dumps(const std::vector<std::string>& requests, Graph& graph) {
  std::vector<Dump> dumps;
  for (const std::string& request : requests) {
    const Where where{"<command line>", "--dump " + request, 0};
    auto fail = [&](const std::string& message) { throw ConfigError({{where, message}}); };
    const size_t dot = request.find('.'), eq = request.find('=');
    if (dot == std::string::npos || eq == std::string::npos || eq < dot) fail("expected --dump PASS.SLOT=FILE");
    const std::string file = request.substr(eq + 1);
    // --dump PASS.SLOT=FILE: what the pass leaves in the slot, kept to the end of the frame (graph/probe.h).
    const uint32_t resource = find_probe(graph, request, where).resource;
    const bool buffer = graph.resources[resource].desc.kind == ResourceKind::buffer;
    if (buffer ? file.size() < 4 || file.compare(file.size() - 4, 4, ".bin") != 0 : !image_format_for(file)) {
      fail(buffer ? "a buffer dumps to a .bin file" : "a texture dumps to a .png, .exr or .pfm file");
    }
    probe_slot(graph, request, where);
    dumps.push_back({resource, file});
  }
  return dumps;
}

void render_frames(rhi::Device& device, const Args& args, LoadedConfig& loaded);

int render(const Args& args, LoadedConfig loaded) {
  const std::optional<SimulatedFault> fault = simulated_fault();
  if (!fault) return bad_usage("VOLGRAPH_SIMULATE_FAULT must be out_of_memory or device_lost");
  if (args.backend == "webgpu") {
    if (args.device >= 0) return bad_usage("--device picks a Vulkan device; WebGPU uses Dawn's default adapter");
    const std::unique_ptr<rhi::Device> device = create_webgpu_device(*fault);
    render_frames(*device, args, loaded);  // Dawn's errors throw as DeviceErrors
    return kOk;
  }
  auto context = vulkan::Context::create({.validation = args.validation, .device_index = args.device, .simulate = *fault});
  vulkan::VulkanDevice device(*context);
  render_frames(device, args, loaded);
  const auto messages = context->take_validation_messages();
  for (const std::string& m : messages) std::cerr << "validation: " << m << "\n";
  return messages.empty() ? kOk : kFailure;
}

void stage_image(OutputFiles& files, const std::string& path, const std::string& flag, const Image& image) {
  files.stage(path, flag, encode_image(image, *image_format_for(path)));  // the type was checked
}

// Renders the frames on `device` and writes the output, the dumps and the timings: all
// of them, renamed into place together once every one is written, or none.
void render_frames(rhi::Device& device, const Args& args, LoadedConfig& loaded) {
  const std::vector<Dump> dumps = add_dumps(args.dumps, loaded.graph);
  Executor executor(device, loaded.graph, &loaded.config.scene, args.compile);
  for (int f = 0; f < args.frames; ++f) executor.run_frame();
  OutputFiles files;
  const Texels texels = executor.read_output(0);
  stage_image(files, args.output, "-o", Image{texels.width, texels.height, texels.rgba});
  for (const Dump& d : dumps) {
    if (loaded.graph.resources[d.resource].desc.kind == ResourceKind::buffer) {
      files.stage(d.file, "--dump", executor.read_buffer(d.resource));
    } else {
      const Texels t = executor.read_texture(d.resource);  // a 3D texture: its slices stacked, slice 0 on top
      stage_image(files, d.file, "--dump", Image{t.width, t.height * t.depth, t.rgba});
    }
  }
  const std::string timings = timings_json(executor.timings(), device, args.frames, executor.frame_wall_ms());
  if (!args.timings_out.empty()) files.stage(args.timings_out, "--timings-out", std::as_bytes(std::span(timings)));
  files.commit();
  if (args.timings) std::cout << timings;
}

// What `plan --backend webgpu` says first: WebGPU pools whole objects instead of aliasing.
std::string webgpu_memory_line(const Graph& graph, const Plan& plan) {
  const ResourcePool pool = pool_resources(graph, plan);
  std::ostringstream o;
  o << "backend webgpu: no placed memory; transient resources are pooled — " << pool.transient_objects << " objects, "
    << bytes_text(pool.transient_bytes) << " (the \"pooled\" figure below)\n\n";
  return o.str();
}

// The CPU ground truth (reference/): the config's scene only, its size from output.size
// or --size.
int reference_render(const Args& args, const LoadedConfig& loaded) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<reference::Renderer> renderer;
  try {
    reference::IntegrationSettings integration;
    integration.relative_tolerance = args.tolerance;
    integration.clouds = reference::cloud_reference_settings(loaded.graph, loaded.params);  // the config's cloud passes
    reference::AtmosphereReferenceSettings atmosphere;
    atmosphere.samples = uint32_t(args.atmosphere_paths);
    renderer.emplace(loaded.config.scene, integration, atmosphere);
    if (const std::string why = renderer->media().under_resolved(); !why.empty()) std::cerr << "volgraph reference: warning: " << why << "\n";
  } catch (const std::runtime_error& e) {  // a model or texture the loader accepted but cannot be read now
    throw ConfigError({{{args.config, "/scene", 0}, e.what()}});
  }
  reference::RenderSettings settings;
  settings.width = loaded.config.output_size.width;
  settings.height = loaded.config.output_size.height;
  settings.samples_per_axis = uint32_t(args.samples_per_axis);
  settings.threads = unsigned(args.threads);
  settings.progress = isatty(STDERR_FILENO) ? &std::cerr : nullptr;
  reference::ReferenceImage image;
  try {
    image = reference::render_image(*renderer, settings);
  } catch (const std::bad_alloc&) {
    const double mib = double(settings.width) * settings.height * 3 * sizeof(double) / (1 << 20);
    throw OutOfHostMemory("the reference image, " + std::to_string(settings.width) + "×" + std::to_string(settings.height) +
                          " pixels of 3 doubles (" + std::to_string(int64_t(std::ceil(mib))) + " MiB)");
  }
  Image out{image.width, image.height, std::vector<float>(size_t(image.width) * image.height * 4, 1.0f)};
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
    for (size_t c = 0; c < 3; ++c) out.rgba[p * 4 + c] = float(image.rgb[p * 3 + c]);
  }
  OutputFiles files;
  stage_image(files, args.output, "-o", out);
  files.commit();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "reference: " << image.width << "×" << image.height << " in " << std::fixed << std::setprecision(2) << seconds << " s\n";
  return kOk;
}

// The commands: each runs on the parsed arguments (the command line is checked already).

// The config loaded once at its own size; --size then resizes the graph (extents are
// resolved for a frame size when it is compiled, graph.h resize()), as a viewer does.
LoadedConfig load(const Args& args, const PassRegistry& registry) {
  if (args.config.empty()) throw UsageError(args.command + " needs a CONFIG file");
  Overrides at_own_size = args.overrides;
  at_own_size.size.reset();
  LoadedConfig loaded = load_config(args.config, registry, at_own_size);
  for (const Diagnostic& w : loaded.warnings) std::cerr << format_warning(w) << "\n";
  if (args.overrides.size) {
    loaded.config.output_size = *args.overrides.size;
    resize(loaded.graph, *args.overrides.size);
  }
  return loaded;
}

int run_validate(const Args& args, const PassRegistry& registry) {
  LoadedConfig loaded = load(args, registry);
  const Plan plan = compile_loaded(loaded, args.compile);
  std::cout << args.config << ": valid (" << plan.order.size() << " passes run, " << plan.culled.size() << " culled)\n";
  return kOk;
}

// The plan as an executor runs it on --backend's device, every pass set up (its setup notes filled).
Plan set_up_plan(const Args& args, LoadedConfig& loaded) {
  if (args.backend == "webgpu") {
    const std::unique_ptr<rhi::Device> device = create_webgpu_device(SimulatedFault::none);
    return Executor(*device, loaded.graph, &loaded.config.scene, args.compile).plan();
  }
  auto context = vulkan::Context::create({.validation = args.validation, .device_index = args.device});
  vulkan::VulkanDevice device(*context);
  return Executor(device, loaded.graph, &loaded.config.scene, args.compile).plan();
}

int run_plan(const Args& args, const PassRegistry& registry) {
  LoadedConfig loaded = load(args, registry);
  const Plan plan = args.setup ? set_up_plan(args, loaded) : compile_loaded(loaded, args.compile);
  const PlanReportContext context{args.config};
  if (args.backend == "webgpu" && !args.json && !args.dot) std::cout << webgpu_memory_line(loaded.graph, plan);
  std::cout << (args.json ? plan_json(loaded.graph, plan, context)
                : args.dot ? plan_dot(loaded.graph, plan, context)
                           : plan_text(loaded.graph, plan, context));
  return kOk;
}

// The file a --dump request names ("" when it names none; add_dumps reports that).
std::string dump_file(const std::string& request) {
  const size_t eq = request.find('=');
  return eq == std::string::npos ? "" : request.substr(eq + 1);
}

// Every file the command will write, checked before any work: -o of a type we write,
// each target a file in an existing folder, and no two outputs (nor an output and the
// config) the same file, which would leave only the last writer's.
void check_outputs(const Args& args) {
  if (args.output.empty()) throw UsageError(args.command + " needs -o OUT (.png, .exr or .pfm)");
  if (!image_format_for(args.output)) {
    throw ConfigError({{{"<command line>", "-o " + args.output, 0}, "unsupported image type; expected a .png, .exr or .pfm file name"}});
  }
  std::vector<std::pair<std::string, std::string>> files = {{"-o", args.output}};  // flag, file
  if (!args.timings_out.empty()) files.push_back({"--timings-out", args.timings_out});
  for (const std::string& d : args.dumps) {
    if (!dump_file(d).empty()) files.push_back({"--dump", dump_file(d)});
  }
  std::vector<std::pair<std::string, std::filesystem::path>> seen = {{"the config", std::filesystem::path(canonical_path_text(args.config))}};
  for (const auto& [flag, file] : files) {
    check_output_target(file, flag);
    const std::filesystem::path canonical(canonical_path_text(file));
    for (const auto& [other, path] : seen) {
      if (path == canonical) {
        throw UsageError(flag + " " + file + " is the same file as " + other + "; expected a different file for each output");
      }
    }
    seen.push_back({flag + " " + file, canonical});
  }
}

int run_render(const Args& args, const PassRegistry& registry) {
  check_outputs(args);
  LoadedConfig loaded = load(args, registry);
  compile_loaded(loaded, args.compile);  // the config's errors before any device work
  return render(args, std::move(loaded));
}

int run_reference(const Args& args, const PassRegistry& registry) {
  check_outputs(args);
  return reference_render(args, load(args, registry));
}

// view CONFIG: the config checked and compiled as `render` does (its errors, exit 2,
// before any window), then the window (viewer/).
int run_view(const Args& args, const PassRegistry& registry) {
  // Not the command line's fault: one line, without bad_usage's pointer to --help.
  auto setup_missing = [](const std::string& message) {
    std::cerr << "volgraph: " << message << "\n";
    return kBadInput;
  };
  if (!args.screenshot.empty()) {
    if (image_format_for(args.screenshot) != ImageFormat::png) {
      throw UsageError("--screenshot " + args.screenshot + ": expected a .png file name");
    }
    check_output_target(args.screenshot, "--screenshot");
  }
  if (!args.script.empty() && args.view_frames > 0) {
    throw UsageError("--script and --frames: the script's `frames N` lines say how many frames to render");
  }
  if (args.backend == "webgpu" && args.device >= 0) throw UsageError("--device picks a Vulkan device; WebGPU uses Dawn's default adapter");
  viewer::ViewOptions options;
  options.scripted = !args.script.empty();
  if (options.scripted) options.script = viewer::read_script(args.script);
  LoadedConfig loaded = load(args, registry);
  compile_loaded(loaded, args.compile);
  options.frames = args.view_frames;
  options.screenshot = args.screenshot;
  options.validation = args.validation;
  options.backend = args.backend;
  if (!args.shaders.empty() && !std::filesystem::is_directory(args.shaders)) {
    throw UsageError("--shaders " + args.shaders + ": expected a folder of shader sources (laid out as shaders/)");
  }
  options.shaders = args.shaders;
  options.overlay = !args.no_overlay;
  options.device = args.device;
  options.compile = args.compile;
  options.title = "volgraph view " + args.config;
  options.config = args.config;
  options.registry = &registry;
  options.overrides = args.overrides;
  try {
    return viewer::run(std::move(loaded), options);
  } catch (const viewer::NoDisplay& e) {
    return setup_missing(e.what());
  }
}

void declare_view(CLI::App& app, Args& args) {
  config_argument(app, args);
  graph_options(app, args);
  view_options(app, args);
}

// passes and devices take no arguments and no options: a word after them is bad input.
void no_arguments(CLI::App&, Args&) {}
void check_no_arguments(const Args& args) {
  if (!args.config.empty()) throw UsageError(args.command + " takes no arguments, got \"" + args.config + "\"");
}

int run_passes(const Args& args, const PassRegistry& registry) {
  check_no_arguments(args);
  return print_passes(registry);
}

int run_devices(const Args& args, const PassRegistry&) {
  check_no_arguments(args);
  return print_devices();
}

// The options of each comparison command: the shared ones and its own.
void declare_ab(CLI::App& app, Args& args) {
  config_argument(app, args);
  graph_options(app, args);
  output_option(app, args);
  render_options(app, args);
  reference_options(app, args);
  timing_options(app, args);
  ab_options(app, args);
}

void declare_sweep(CLI::App& app, Args& args) {
  config_argument(app, args);
  output_option(app, args);
  reference_options(app, args);
  timing_options(app, args);
  sweep_options(app, args);
}

void declare_tune(CLI::App& app, Args& args) {
  declare_sweep(app, args);
  tune_options(app, args);
}

// Every command: its name, the options it declares (tools/command_line.h) and what runs
// it. A new command is a row here with its own two functions, e.g. a declare function
// that calls config_argument and graph_options and adds its own options.
constexpr Command kCommands[] = {
    {"validate", every_option, run_validate},
    {"plan", every_option, run_plan},
    {"render", every_option, run_render},
    {"reference", every_option, run_reference},
    {"passes", no_arguments, run_passes},
    {"devices", no_arguments, run_devices},
    {"ab", declare_ab, run_ab},
    {"sweep", declare_sweep, run_sweep_command},
    {"tune", declare_tune, run_tune},
    {"view", declare_view, run_view},
};

// --device N names a device that exists: an index past the last one is bad input, said
// before any work or output (the indices count the Vulkan 1.3 devices, as
// vulkan::Context picks them). With no such device at all, the render says so (exit 1).
void check_device_index(const Args& args) {
  if (args.device < 0) return;
  size_t count = 0;
  for (const auto& d : vulkan::Context::list_devices()) count += d.api_version >= VK_API_VERSION_1_3 ? 1 : 0;
  if (count == 0 || size_t(args.device) < count) return;
  throw UsageError("--device " + std::to_string(args.device) + ": no such Vulkan device; there " +
                   (count == 1 ? std::string("is 1 (index 0)") : "are " + std::to_string(count) + " (indices 0 to " + std::to_string(count - 1) + ")") +
                   ", listed by volgraph devices");
}

int run(const Args& args, const PassRegistry& registry) {
  for (const char* uses_device : {"render", "ab", "sweep", "tune", "view"}) {
    if (args.command == uses_device) check_device_index(args);
  }
  for (const Command& command : kCommands) {
    if (args.command == command.name) return command.run(args, registry);
  }
  return bad_usage("unknown command \"" + args.command + "\"");
}

}  // namespace
}  // namespace volgraph

// What kind of failure the driver reported, in the user's terms.
const char* device_error_heading(volgraph::DeviceError::Kind kind) {
  using volgraph::DeviceError;
  switch (kind) {
    case DeviceError::Kind::out_of_memory: return "out of device memory: ";
    case DeviceError::Kind::device_lost: return "device lost (the driver stopped or was reset): ";
    case DeviceError::Kind::no_device: return "no usable GPU: ";
    case DeviceError::Kind::unsupported: return "";
    case DeviceError::Kind::other: break;
  }
  return "device error: ";
}

int main(int argc, char** argv) {
  using namespace volgraph;
  Args args;
  if (auto code = parse_command_line(argc, argv, kCommands, args)) return *code;
  PassRegistry registry;
  register_builtin_passes(registry);
  try {
    return run(args, registry);
  } catch (const UsageError& e) {
    return bad_usage(e.what());
  } catch (const ConfigError& e) {
    std::cerr << e.what() << "\n";
    return kBadInput;
  } catch (const DeviceError& e) {
    std::cerr << "volgraph: " << device_error_heading(e.kind) << e.what() << "\n";
    return kFailure;
  } catch (const IoError& e) {
    std::cerr << "volgraph: cannot write " << e.what() << "\n";
    return kFailure;
  } catch (const OutOfHostMemory& e) {
    std::cerr << "volgraph: out of host memory: " << e.what() << "\n";
    return kFailure;
  } catch (const std::bad_alloc&) {
    std::cerr << "volgraph: out of host memory (" << args.command << " " << args.config << ": an allocation failed)\n";
    return kFailure;
  } catch (const std::exception& e) {
    std::cerr << "volgraph: internal error: " << e.what() << "\n";
    return kFailure;
  }
}
