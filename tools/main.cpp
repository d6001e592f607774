// The volgraph command line (DESIGN.md "Command line"). Exit codes: 0 success,
// 1 failure that is not the input's fault, 2 bad input (one clear message each).
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "graph/config/config.h"
#include "graph/plan_report.h"
#include "graph/rhi/device_error.h"
#include "graph/rhi/vulkan/context.h"
#include "passes/passes.h"

namespace volgraph {
namespace {

constexpr int kOk = 0, kFailure = 1, kBadInput = 2;

const char* kUsage = R"(usage: volgraph COMMAND [options]

commands:
  validate CONFIG              check a config without a GPU (exit 0 valid, 2 invalid)
  plan CONFIG [--json|--dot]   the compiled plan: order, culling, lifetimes, memory, barriers
  render CONFIG -o OUT         render to .png, .exr or .pfm (arrives with the Vulkan backend)
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
)";

struct Args {
  std::string command;
  std::string config;
  std::string output;
  bool json = false, dot = false;
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
      break;
    case SizeSpec::Mode::square_param:
      out = s.size.param + "²";
      break;
  }
  if (s.kind == ResourceKind::texture3d) out += " × " + std::to_string(s.size.absolute.depth);
  return out;
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
      const char* dir = s.direction == SlotDirection::input ? "in" : s.direction == SlotDirection::output ? "out" : "inout";
      std::cout << "  " << dir << " " << s.name << ": " << kind_name(s.kind) << ", " << usage_name(s.usage);
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

int run(const Args& args, const PassRegistry& registry) {
  if (args.command == "passes") return print_passes(registry);
  if (args.command == "devices") return print_devices();
  const bool known = args.command == "validate" || args.command == "plan" || args.command == "render";
  if (!known) {
    if (args.command == "reference" || args.command == "ab" || args.command == "sweep") {
      std::cerr << "volgraph " << args.command << ": not implemented yet (arrives with the volumetric fog issue)\n";
      return kFailure;
    }
    return bad_usage("unknown command \"" + args.command + "\"");
  }
  if (args.config.empty()) return bad_usage(args.command + " needs a CONFIG file");
  const LoadedConfig loaded = load_config(args.config, registry, args.overrides);
  const Plan plan = compile_loaded(loaded, args.compile);
  const PlanReportContext context{args.config};
  if (args.command == "validate") {
    std::cout << args.config << ": valid (" << plan.order.size() << " passes run, " << plan.culled.size()
              << " culled)\n";
    return kOk;
  }
  if (args.command == "plan") {
    std::cout << (args.json ? plan_json(loaded.graph, plan, context)
                  : args.dot ? plan_dot(loaded.graph, plan, context)
                             : plan_text(loaded.graph, plan, context));
    return kOk;
  }
  std::cerr << "volgraph render: the config is valid, but rendering arrives with the Vulkan backend (issue 3); "
               "no image was written. 'volgraph plan "
            << args.config << "' shows what the render will run.\n";
  return kFailure;
}

}  // namespace
}  // namespace volgraph

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
    std::cerr << "volgraph: device error: " << e.what() << "\n";
    return kFailure;
  } catch (const std::exception& e) {
    std::cerr << "volgraph: internal error: " << e.what() << "\n";
    return kFailure;
  }
}
