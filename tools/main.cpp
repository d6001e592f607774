// The volgraph command line (DESIGN.md "Command line"). Exit codes: 0 success,
// 1 failure that is not the input's fault, 2 bad input (one clear message each).
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <unistd.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "tools/image_io.h"
#include "tools/webgpu_backend.h"
#include "graph/plan_report.h"
#include "graph/pooling.h"
#include "graph/rhi/device_error.h"
#include "graph/rhi/vulkan/context.h"
#include "passes/passes.h"
#include "reference/image_render.h"
#include "reference/media.h"
#include "reference/renderer.h"

namespace volgraph {
namespace {

constexpr int kOk = 0, kFailure = 1, kBadInput = 2;

const char* kUsage = R"(usage: volgraph COMMAND [options]

commands:
  validate CONFIG              check a config without a GPU (exit 0 valid, 2 invalid)
  plan CONFIG [--json|--dot]   the compiled plan: order, culling, lifetimes, memory, barriers
  render CONFIG -o OUT         render to .png (sRGB 8-bit), .exr or .pfm (linear float)
  reference CONFIG -o OUT      the CPU ground truth of the config's scene (double precision, exact
                               visibility; pass parameters such as ambient or tone maps are not part
                               of the scene and are ignored): .exr or .pfm linear float, or .png
                               with linear values clamped to [0, 1] and sRGB-encoded (no tone map)
  passes                       the pass types with their variants, parameters and slots
  devices                      the Vulkan devices (index for --device N; lavapipe is the default)
  test                         run the whole test suite (handled by tools/volgraph)

options (plan, validate, render):
  --size WxH                   frame size (overrides output.size)
  --set PASS.PARAM=VALUE       set a pass parameter (VALUE in JSON: 2, 0.5, true, [1,2,3], word)
  --variant PASS=VARIANT       swap a pass's variant
  --no-cull                    keep every pass (debug)
  --no-alias                   give every transient resource its own memory (debug)
  --serialize                  a full barrier between every two passes (debug)

options (reference):
  --size WxH                   frame size (overrides output.size)
  --threads N                  worker threads (default: the hardware's); the image does not depend on it
  --spp N                      samples per pixel on a regular sub-pixel grid, N a square (1, 4, 9, …);
                               default 1: pixel centres, as the GPU samples
  --tolerance X                relative error allowed in each stretch of the media integral (default 1e-5)

options (render):
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

int bad_usage(const std::string& message) {
  std::cerr << "volgraph: " << message << "\n(run 'volgraph --help' for usage)\n";
  return kBadInput;
}

std::optional<Extent> parse_size(const std::string& text) {
  unsigned w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%u%c%u%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X')) return std::nullopt;
  if (w < 1 || h < 1 || w > 16384 || h > 16384) return std::nullopt;
  return Extent{w, h, 1};
}

// Fills `args`; returns an exit code when parsing must stop there.
std::optional<int> parse(int argc, char** argv, Args& args) {
  std::vector<std::string> words(argv + 1, argv + argc);
  if (words.empty() || words[0] == "--help" || words[0] == "-h" || words[0] == "help") {
    std::cout << kUsage;
    return words.empty() ? kBadInput : kOk;
  }
  args.command = words[0];
  for (size_t i = 1; i < words.size(); ++i) {
    const std::string& w = words[i];
    auto value = [&](const char* flag) -> std::optional<std::string> {
      if (i + 1 < words.size()) return words[++i];
      bad_usage(std::string(flag) + " needs a value");
      return std::nullopt;
    };
    if (w == "--json") args.json = true;
    else if (w == "--dot") args.dot = true;
    else if (w == "--no-cull") args.compile.cull = false;
    else if (w == "--no-alias") args.compile.alias = false;
    else if (w == "--serialize") args.compile.serialize = true;
    else if (w == "--size") {
      const auto v = value("--size");
      if (!v) return kBadInput;
      args.overrides.size = parse_size(*v);
      if (!args.overrides.size) return bad_usage("--size expects WxH with each side in [1, 16384], got \"" + *v + "\"");
    } else if (w == "--set" || w == "--variant") {
      const auto v = value(w.c_str());
      if (!v) return kBadInput;
      (w == "--set" ? args.overrides.sets : args.overrides.variants).push_back(*v);
    } else if (w == "--backend" || w == "--timings-out") {
      const auto v = value(w.c_str());
      if (!v) return kBadInput;
      (w == "--backend" ? args.backend : args.timings_out) = *v;
      if (w == "--backend" && *v != "vulkan" && *v != "webgpu") return bad_usage("--backend expects vulkan or webgpu, got \"" + *v + "\"");
    } else if (w == "--device" || w == "--frames") {
      const auto v = value(w.c_str());
      if (!v) return kBadInput;
      char* end = nullptr;
      const long n = std::strtol(v->c_str(), &end, 10);
      const long low = w == "--device" ? 0 : 1;
      if (*end || n < low || n > 100000) return bad_usage(w + " expects a whole number ≥ " + std::to_string(low) + ", got \"" + *v + "\"");
      (w == "--device" ? args.device : args.frames) = int(n);
    } else if (w == "--threads" || w == "--spp") {
      const auto v = value(w.c_str());
      if (!v) return kBadInput;
      char* end = nullptr;
      const long n = std::strtol(v->c_str(), &end, 10);
      const long root = std::lround(std::sqrt(double(std::max(n, 0L))));
      if (*end || v->empty() || n < 1 || n > 4096) return bad_usage(w + " expects a whole number in [1, 4096], got \"" + *v + "\"");
      if (w == "--spp" && root * root != n) return bad_usage("--spp expects a square number (1, 4, 9, 16, …), got \"" + *v + "\"");
      (w == "--threads" ? args.threads : args.samples_per_axis) = int(w == "--threads" ? n : root);
    } else if (w == "--tolerance") {
      const auto v = value("--tolerance");
      if (!v) return kBadInput;
      char* end = nullptr;
      args.tolerance = std::strtod(v->c_str(), &end);
      if (*end || v->empty() || !(args.tolerance >= 1e-12 && args.tolerance <= 0.1)) {
        return bad_usage("--tolerance expects a number in [1e-12, 0.1], got \"" + *v + "\"");
      }
    } else if (w == "--dump") {
      const auto v = value("--dump");
      if (!v) return kBadInput;
      args.dumps.push_back(*v);
    } else if (w == "--timings") {
      args.timings = true;
    } else if (w == "--validation") {
      args.validation = true;
    } else if (w == "-o" || w == "--output") {
      const auto v = value("-o");
      if (!v) return kBadInput;
      args.output = *v;
    } else if (w.rfind("--", 0) == 0) {
      return bad_usage("unknown option " + w);
    } else if (args.config.empty()) {
      args.config = w;
    } else {
      return bad_usage("unexpected argument \"" + w + "\"");
    }
  }
  return std::nullopt;
}

std::string range_text(const ParamDecl& p) {
  if (p.type == ParamType::choice) {
    std::string out;
    for (const std::string& c : p.choices) out += (out.empty() ? "" : "|") + c;
    return out;
  }
  if (p.type == ParamType::boolean) return "true|false";
  return "[" + param_value_text(p.min) + ", " + param_value_text(p.max) + "]";
}

std::string size_text(const SlotDecl& s) {
  if (!s.like.empty()) return "like " + s.like;
  if (s.kind == ResourceKind::buffer) return std::to_string(s.size.buffer_bytes) + " B";
  std::string out;
  switch (s.size.mode) {
    case SizeSpec::Mode::absolute:
      out = std::to_string(s.size.absolute.width) + "x" + std::to_string(s.size.absolute.height);
      break;
    case SizeSpec::Mode::relative:
      out = s.size.scale_x == 1.0f && s.size.scale_y == 1.0f ? "frame" : "frame × " + param_value_text(double(s.size.scale_x));
      if (!s.size.divisor_param.empty()) out += " / " + s.size.divisor_param;
      break;
    case SizeSpec::Mode::square_param:
      out = s.size.param + "²";
      break;
  }
  if (s.kind != ResourceKind::texture3d) return out;
  std::string depth = std::to_string(s.size.absolute.depth);
  if (s.size.mode == SizeSpec::Mode::relative && !s.size.param.empty()) depth = s.size.param;
  if (s.size.mode == SizeSpec::Mode::square_param && !s.size.depth_param.empty()) depth = s.size.depth_param;
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
        std::cout << ", " << size_text(s);
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
  }
  return kOk;
}

int print_devices() {
  const auto devices = vulkan::Context::list_devices();
  if (devices.empty()) std::cout << "no Vulkan devices\n";
  for (size_t i = 0; i < devices.size(); ++i) {
    const auto& d = devices[i];
    std::cout << i << ": " << d.name << " — " << d.driver << ", Vulkan " << VK_API_VERSION_MAJOR(d.api_version) << "."
              << VK_API_VERSION_MINOR(d.api_version) << "." << VK_API_VERSION_PATCH(d.api_version) << "\n";
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
      << ", \"cpu_ms\": " << t.cpu_ms << "}" << (i + 1 < timings.size() ? "," : "") << "\n";
  }
  o << "  ],\n  \"total_gpu_ms\": " << gpu << ",\n  \"total_cpu_ms\": " << cpu << ",\n  \"frame_wall_ms\": "
    << frame_wall_ms << "\n}\n";
  return o.str();
}

struct Dump {
  uint32_t resource;
  std::string file;
};

// --dump PASS.SLOT=FILE: the resource that slot holds at the end of the pass, kept alive
// to the end of the frame (a graph output) so that no aliasing overwrites it first.
std::vector<Dump> add_dumps(const std::vector<std::string>& requests, Graph& graph) {
  std::vector<Dump> dumps;
  for (const std::string& request : requests) {
    const Where where{"<command line>", "--dump " + request, 0};
    auto fail = [&](const std::string& message) { throw ConfigError({{where, message}}); };
    const size_t dot = request.find('.'), eq = request.find('=');
    if (dot == std::string::npos || eq == std::string::npos || eq < dot) fail("expected --dump PASS.SLOT=FILE");
    const std::string pass = request.substr(0, dot), slot = request.substr(dot + 1, eq - dot - 1), file = request.substr(eq + 1);
    const auto p = std::find_if(graph.passes.begin(), graph.passes.end(), [&](const GraphPass& g) { return g.name == pass; });
    if (p == graph.passes.end()) fail("no pass named \"" + pass + "\"");
    const int s = p->decl->slot_index(slot);
    const auto use = std::find_if(p->uses.begin(), p->uses.end(), [&](const ResourceUse& u) { return int(u.slot) == s; });
    if (s < 0 || use == p->uses.end()) fail("pass \"" + pass + "\" has no bound slot \"" + slot + "\"");
    const uint32_t version = use->direction == SlotDirection::inout ? use->version + 1 : use->version;
    const GraphResource& r = graph.resources[use->resource];
    if (version + 1 != r.version_writers.size()) {
      fail(pass + "." + slot + " is modified later by pass \"" + graph.passes[r.version_writers[version + 1]].name +
           "\"; dump that pass's slot");
    }
    const bool buffer = r.desc.kind == ResourceKind::buffer;
    if (buffer ? file.size() < 4 || file.compare(file.size() - 4, 4, ".bin") != 0 : !image_format_for(file)) {
      fail(buffer ? "a buffer dumps to a .bin file" : "a texture dumps to a .png, .exr or .pfm file");
    }
    if (std::find(graph.outputs.begin(), graph.outputs.end(), ResourceVersion{use->resource, version}) == graph.outputs.end()) {
      graph.outputs.push_back({use->resource, version});
    }
    dumps.push_back({use->resource, file});
  }
  return dumps;
}

void write_bytes(const std::string& file, const std::vector<std::byte>& bytes) {
  const std::string temporary = file + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out) throw ConfigError({{{"<command line>", "--dump " + file, 0}, "cannot write it"}});
  }
  std::rename(temporary.c_str(), file.c_str());
}

// VOLGRAPH_SIMULATE_FAULT=out_of_memory|device_lost makes the driver fail (to test how
// failures are reported); none when unset, nullopt for another value.
std::optional<vulkan::SimulatedFault> simulated_fault() {
  const char* value = std::getenv("VOLGRAPH_SIMULATE_FAULT");
  if (!value || !*value) return vulkan::SimulatedFault::none;
  if (std::string_view(value) == "out_of_memory") return vulkan::SimulatedFault::out_of_memory;
  if (std::string_view(value) == "device_lost") return vulkan::SimulatedFault::device_lost;
  return std::nullopt;
}

void render_frames(rhi::Device& device, const Args& args, LoadedConfig& loaded);

int render(const Args& args, LoadedConfig loaded) {
  if (args.output.empty()) return bad_usage("render needs -o OUT (.png, .exr or .pfm)");
  if (!image_format_for(args.output)) {
    throw ConfigError({{{"<command line>", "-o " + args.output, 0}, "unsupported image type; expected a .png, .exr or .pfm file name"}});
  }
  const std::optional<vulkan::SimulatedFault> fault = simulated_fault();
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

// Renders the frames on `device` and writes the output, the dumps and the timings.
void render_frames(rhi::Device& device, const Args& args, LoadedConfig& loaded) {
  const std::vector<Dump> dumps = add_dumps(args.dumps, loaded.graph);
  Executor executor(device, loaded.graph, &loaded.config.scene, args.compile);
  for (int f = 0; f < args.frames; ++f) executor.run_frame();
  const Texels texels = executor.read_output(0);
  write_image(args.output, Image{texels.width, texels.height, texels.rgba});
  for (const Dump& d : dumps) {
    if (loaded.graph.resources[d.resource].desc.kind == ResourceKind::buffer) {
      write_bytes(d.file, executor.read_buffer(d.resource));
    } else {
      const Texels t = executor.read_texture(d.resource);  // a 3D texture: its slices stacked, slice 0 on top
      write_image(d.file, Image{t.width, t.height * t.depth, t.rgba}, "--dump");
    }
  }
  const std::string timings = timings_json(executor.timings(), device, args.frames, executor.frame_wall_ms());
  if (args.timings) std::cout << timings;
  if (!args.timings_out.empty()) std::ofstream(args.timings_out) << timings;
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
  if (args.output.empty()) return bad_usage("reference needs -o OUT (.png, .exr or .pfm)");
  if (!image_format_for(args.output)) {
    throw ConfigError({{{"<command line>", "-o " + args.output, 0}, "unsupported image type; expected a .png, .exr or .pfm file name"}});
  }
  const auto start = std::chrono::steady_clock::now();
  std::optional<reference::Renderer> renderer;
  try {
    reference::IntegrationSettings integration;
    integration.relative_tolerance = args.tolerance;
    renderer.emplace(loaded.config.scene, integration);
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
  const reference::ReferenceImage image = reference::render_image(*renderer, settings);
  Image out{image.width, image.height, std::vector<float>(size_t(image.width) * image.height * 4, 1.0f)};
  for (size_t p = 0; p < size_t(image.width) * image.height; ++p) {
    for (size_t c = 0; c < 3; ++c) out.rgba[p * 4 + c] = float(image.rgb[p * 3 + c]);
  }
  write_image(args.output, out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "reference: " << image.width << "×" << image.height << " in " << std::fixed << std::setprecision(2) << seconds << " s\n";
  return kOk;
}

int run(const Args& args, const PassRegistry& registry) {
  if (args.command == "passes") return print_passes(registry);
  if (args.command == "devices") return print_devices();
  const bool known = args.command == "validate" || args.command == "plan" || args.command == "render" || args.command == "reference";
  if (!known) {
    if (args.command == "ab" || args.command == "sweep") {
      std::cerr << "volgraph " << args.command << ": not implemented yet (arrives with the volumetric fog issue)\n";
      return kFailure;
    }
    return bad_usage("unknown command \"" + args.command + "\"");
  }
  if (args.config.empty()) return bad_usage(args.command + " needs a CONFIG file");
  LoadedConfig loaded = load_config(args.config, registry, args.overrides);
  if (args.command == "reference") return reference_render(args, loaded);
  const Plan plan = compile_loaded(loaded, args.compile);
  const PlanReportContext context{args.config};
  if (args.command == "validate") {
    std::cout << args.config << ": valid (" << plan.order.size() << " passes run, " << plan.culled.size()
              << " culled)\n";
    return kOk;
  }
  if (args.command == "plan") {
    if (args.backend == "webgpu" && !args.json && !args.dot) std::cout << webgpu_memory_line(loaded.graph, plan);
    std::cout << (args.json ? plan_json(loaded.graph, plan, context)
                  : args.dot ? plan_dot(loaded.graph, plan, context)
                             : plan_text(loaded.graph, plan, context));
    return kOk;
  }
  return render(args, std::move(loaded));
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
  if (auto code = parse(argc, argv, args)) return *code;
  PassRegistry registry;
  register_builtin_passes(registry);
  try {
    return run(args, registry);
  } catch (const ConfigError& e) {
    std::cerr << e.what() << "\n";
    return kBadInput;
  } catch (const DeviceError& e) {
    std::cerr << "volgraph: " << device_error_heading(e.kind) << e.what() << "\n";
    return kFailure;
  } catch (const std::exception& e) {
    std::cerr << "volgraph: internal error: " << e.what() << "\n";
    return kFailure;
  }
}
