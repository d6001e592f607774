// Benchmark (not a test): run time against error. Each fog technique over its quality
// settings on configs/demo_fog.json, rendered on Vulkan (lavapipe) frame after frame —
// the median frame wall time (submit to completion, GPU time stamps off) — and its
// first frame compared with the CPU reference of the same scene and size (computed
// once; linear outputs, composite forced to `none`; fog-only pixels and metric of
// tests/support/fog_accuracy.h). Settings take turns frame by frame, so a change in the
// machine's load falls on all of them alike. Prints the table with the ratio to the
// fastest setting and marks the Pareto-optimal rows (no other row is both faster and
// closer).
// One change makes the demo comparable with the reference, applied to both renders: the
// camera's far plane is brought to the froxel grid's far end (the reference integrates
// the media to the far plane, the grid stops at its `far`).
// The light_volume sweep runs configs/demo_light_volume.json (homogeneous fog, a spot
// light's 512² shadow map) instead: light_volume at each variant and grid against
// raymarch_fog at 50 … 400 midpoint steps (jitter off; the light dimmed by the fog in
// closed form, as light_volume does), the camera's far plane (and the march's max_distance) at 20 m; its
// rows are also compared with a 1000-step march over every pixel (the same shadow map,
// so what is left is each technique's own error).
// The demos table (`demos`, no timing): every configs/demo_*.json (or the CONFIGs named),
// its first frame against the reference of the same size — relative mean error over all
// pixels, over the fog-only pixels and over the surface-only pixels (the pixel and its 3×3
// neighbourhood all see a surface), the metric of tests/support/fog_accuracy.h — as
// shipped, and like for like: the terms the reference does not model left out on both
// sides (every pass's `ambient` set to 0; the camera's far plane brought to where the
// technique's media end, the froxel grid's `far` or raymarch_fog's `max_distance`).
//   bench_fog_sweep [FRAMES] [WxH] [froxel|light_volume|demos [CONFIG...]]
//     default 5 frames at 320x180, after one warm-up frame, the froxel sweep
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/passes.h"
#include "tests/support/fog_accuracy.h"

namespace volgraph {
namespace {

const std::string kDemo = std::string(VOLGRAPH_SOURCE_DIR) + "/configs/demo_fog.json";
const std::string kLightVolumeDemo = std::string(VOLGRAPH_SOURCE_DIR) + "/configs/demo_light_volume.json";
constexpr double kLightVolumeFar = 20;  // m: the camera's far plane and the march's max_distance

// One row of the sweep: a technique at one quality setting, as overrides of the demo,
// or (`fog_pass` not empty) the demo with its fog_volume pass replaced by this one.
struct Setting {
  std::string technique;
  std::string label;
  Overrides overrides;
  std::string fog_pass;
};

// A sweep: the demo, its settings, and (optionally) the setting whose image every row is
// also compared with over all pixels.
struct Sweep {
  std::string demo;
  std::vector<Setting> settings;
  std::optional<Setting> gpu_reference;
};

struct Row {
  Setting setting;
  double frame_ms = 0;
  accuracy::FogComparison fog_only;  // the fog-only pixels (the figure the front is taken on)
  accuracy::FogComparison all;       // every pixel, surfaces too (differences outside the technique included)
  std::optional<accuracy::FogComparison> against_gpu;  // every pixel, against the sweep's GPU reference
  bool pareto = false;
};

std::vector<Setting> froxel_settings() {
  std::vector<Setting> out;
  for (const char* integration : {"wronski", "hillaire"}) {
    for (int shadow : {512, 2048}) {
      for (int slices : {16, 32, 64, 128}) {
        Overrides o;
        o.sets = {"fog_media.slices=" + std::to_string(slices), "sun_shadow.resolution=" + std::to_string(shadow)};
        o.variants = {"fog_integral=" + std::string(integration)};
        out.push_back({"froxel", std::string(integration) + ", " + std::to_string(slices) + " slices, shadow " + std::to_string(shadow), o, ""});
      }
    }
  }
  for (const auto [side, layers] : {std::pair{32, 16}, std::pair{128, 64}}) {  // the opacity shadow map's size (default 64² × 32)
    Overrides o;
    o.sets = {"fog_media.slices=32", "sun_shadow.resolution=512", "media_shadow.resolution=" + std::to_string(side),
              "media_shadow.layers=" + std::to_string(layers)};
    o.variants = {"fog_integral=hillaire"};
    const std::string size = std::to_string(side) + "²×" + std::to_string(layers);
    out.push_back({"froxel", "hillaire, 32 slices, shadow 512, opacity " + size, o, ""});
  }
  return out;
}

// raymarch_fog in light_volume's place, as the demo wires it.
Setting march_setting(int steps) {
  const std::string params = R"({ "steps": )" + std::to_string(steps) + R"(, "jitter": false, "max_distance": )" +
                             std::to_string(kLightVolumeFar) + " }";
  return {"raymarch", std::to_string(steps) + " steps", {},
          R"({ "name": "fog_volume", "type": "raymarch_fog", "params": )" + params +
              R"(, "inputs": { "depth": "lit.depth", "shadow_map": "sun_shadow.depth", "light_view": "sun_shadow.light_view" } })"};
}

Sweep light_volume_sweep() {
  Sweep sweep{kLightVolumeDemo, {}, march_setting(1000)};
  for (const char* variant : {"height_field", "texel_steps"}) {
    for (int grid : {64, 128, 256, 512}) {
      Overrides o;
      o.sets = {"fog_volume.grid=" + std::to_string(grid)};
      o.variants = {"fog_volume=" + std::string(variant)};
      sweep.settings.push_back({"light_vol", std::string(variant) + ", grid " + std::to_string(grid), o, ""});
    }
  }
  for (int steps : {50, 100, 200, 400}) sweep.settings.push_back(march_setting(steps));
  return sweep;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0 : values[values.size() / 2];
}

// The froxel grid's far end (m), or the camera's far plane when the graph has no grid.
double grid_far(const LoadedConfig& loaded) {
  for (const GraphPass& pass : loaded.graph.passes) {
    if (pass.decl->name != "froxel_voxelize" || pass.params.empty()) continue;
    return std::get<double>(pass.params[size_t(pass.decl->param_index("far"))]);
  }
  return loaded.config.scene.camera.far;
}

// The change of the file comment.
void make_comparable(LoadedConfig& loaded) { loaded.config.scene.camera.far = grid_far(loaded); }

LoadedConfig load_setting(const PassRegistry& registry, const std::string& demo, Extent size, const Setting& setting) {
  Overrides overrides = setting.overrides;
  overrides.size = size;
  LoadedConfig loaded = setting.fog_pass.empty()
                            ? accuracy::load_linear(demo, registry, overrides)
                            : accuracy::load_linear_text(setting.label, R"({ "include": ")" + demo + R"(", "graph": { "passes": [ )" +
                                                                            setting.fog_pass + " ] } }",
                                                         registry, overrides);
  make_comparable(loaded);
  if (demo == kLightVolumeDemo) loaded.config.scene.camera.far = kLightVolumeFar;
  return loaded;
}

// A GPU image in the reference's form, to compare other images with it.
reference::ReferenceImage as_reference(const Texels& t) {
  reference::ReferenceImage r;
  r.width = t.width;
  r.height = t.height;
  for (size_t i = 0; i < t.rgba.size(); i += 4) r.rgb.insert(r.rgb.end(), {double(t.rgba[i]), double(t.rgba[i + 1]), double(t.rgba[i + 2])});
  return r;
}

// A setting's executor and its frame times so far.
struct Running {
  std::unique_ptr<Executor> executor;
  std::vector<double> walls;
};

// Frame 0 (warm-up, froxels sampled at their centres) of every setting compared with the
// reference, then `frames` rounds of one frame per setting in turn, so that the
// machine's load changes every setting's times alike.
std::vector<Row> measure(rhi::Device& device, const std::vector<LoadedConfig>& configs, const std::vector<Setting>& settings,
                         const reference::ReferenceImage& ref, const std::vector<bool>& fog_only, const std::optional<Texels>& gpu_ref,
                         int frames) {
  std::vector<Row> rows;
  std::vector<Running> running;
  for (size_t i = 0; i < settings.size(); ++i) {
    running.push_back({std::make_unique<Executor>(device, configs[i].graph, &configs[i].config.scene, CompileOptions{}), {}});
    running.back().executor->set_gpu_timing(false);
    running.back().executor->run_frame();
    const Texels first = running.back().executor->read_output(0);
    const std::vector<bool> every(fog_only.size(), true);
    rows.push_back({settings[i], 0, accuracy::compare_fog(first, ref, fog_only), accuracy::compare_fog(first, ref, every)});
    if (gpu_ref) rows.back().against_gpu = accuracy::compare_fog(first, as_reference(*gpu_ref), every);
  }
  for (int f = 0; f < frames; ++f) {
    for (Running& r : running) {
      r.executor->run_frame();
      r.walls.push_back(r.executor->frame_wall_ms());
    }
  }
  for (size_t i = 0; i < rows.size(); ++i) rows[i].frame_ms = median(running[i].walls);
  return rows;
}

void mark_pareto(std::vector<Row>& rows) {
  for (Row& r : rows) {
    r.pareto = std::none_of(rows.begin(), rows.end(), [&](const Row& o) {
      const double oe = o.fog_only.difference.relative_mean_error, re = r.fog_only.difference.relative_mean_error;
      return o.frame_ms <= r.frame_ms && oe <= re && (o.frame_ms < r.frame_ms || oe < re);
    });
  }
}

void print(const std::vector<Row>& rows, const accuracy::FogComparison& coverage) {
  double fastest = rows.front().frame_ms;
  for (const Row& r : rows) fastest = std::min(fastest, r.frame_ms);
  std::printf("\nerror: relative mean absolute error against the reference over the %zu of %zu fog-only pixels "
              "(all pixels in brackets); * Pareto-optimal on time and fog-only error\n",
              coverage.compared_pixels, coverage.pixels);
  const bool against_gpu = rows.front().against_gpu.has_value();
  if (against_gpu) std::printf("vs 1000-step march: the same error against a 1000-step raymarch_fog (same shadow map), every pixel\n");
  std::printf("%-10s %-44s %10s %8s %12s %12s %s%s\n", "technique", "setting", "frame ms", "ratio", "error", "(all px)",
              against_gpu ? "vs march1000 " : "", "front");
  for (const Row& r : rows) {
    std::printf("%-10s %-44s %10.2f %8.2f %12.4f %12.4f ", r.setting.technique.c_str(), r.setting.label.c_str(), r.frame_ms,
                r.frame_ms / fastest, r.fog_only.difference.relative_mean_error, r.all.difference.relative_mean_error);
    if (r.against_gpu) std::printf("%12.5f ", r.against_gpu->difference.relative_mean_error);
    std::printf("%s\n", r.pareto ? "*" : "");
  }
}

int run(int frames, Extent size, const Sweep& sweep) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto context = vulkan::Context::create({});
  vulkan::VulkanDevice device(*context);
  std::printf("bench_fog_sweep: %s at %ux%u, %d frames after one warm-up, median frame wall time; "
              "lavapipe (CPU): its \"GPU\" is this CPU (%s)\n",
              sweep.demo.c_str(), size.width, size.height, frames, device.info().device.c_str());
  const std::vector<Setting>& settings = sweep.settings;
  const LoadedConfig base = load_setting(registry, sweep.demo, size, settings.front());
  const reference::ReferenceImage ref = accuracy::render_reference(base);
  const std::vector<bool> fog_only = accuracy::fog_only_pixels(base.config.scene, size.width, size.height);
  std::optional<Texels> gpu_ref;
  if (sweep.gpu_reference) gpu_ref = accuracy::render_gpu(device, load_setting(registry, sweep.demo, size, *sweep.gpu_reference));
  std::vector<LoadedConfig> configs;
  for (const Setting& setting : settings) configs.push_back(load_setting(registry, sweep.demo, size, setting));
  std::vector<Row> rows = measure(device, configs, settings, ref, fog_only, gpu_ref, frames);
  mark_pareto(rows);
  print(rows, rows.front().fog_only);
  return 0;
}

// Parameter `name` of `pass` (its defaults filled in first when it has none set).
ParamValue& param_of(GraphPass& pass, const std::string& name) {
  if (pass.params.empty()) {
    for (const ParamDecl& p : pass.decl->params) pass.params.push_back(p.default_value);
  }
  return pass.params[size_t(pass.decl->param_index(name))];
}

// Where the fog technique's media end (m of view depth): the froxel grid's far end,
// raymarch_fog's max_distance, else the camera's far plane.
double technique_reach(LoadedConfig& loaded) {
  double reach = loaded.config.scene.camera.far;
  for (GraphPass& pass : loaded.graph.passes) {
    if (pass.decl->name == "froxel_voxelize") reach = std::min(reach, std::get<double>(param_of(pass, "far")));
    if (pass.decl->name == "raymarch_fog") reach = std::min(reach, std::get<double>(param_of(pass, "max_distance")));
  }
  return reach;
}

// The like-for-like change of the file comment.
void leave_out_unmodelled_terms(LoadedConfig& loaded) {
  loaded.config.scene.camera.far = technique_reach(loaded);
  for (GraphPass& pass : loaded.graph.passes) {
    if (pass.decl->param_index("ambient") >= 0) param_of(pass, "ambient") = std::array<double, 3>{0, 0, 0};
  }
}

struct DemoErrors {
  double all = 0, fog_only = 0, surfaces = 0;
  size_t fog_pixels = 0, surface_pixels = 0;
};

DemoErrors demo_errors(rhi::Device& device, const LoadedConfig& loaded) {
  const Extent size = loaded.config.output_size;
  const reference::ReferenceImage ref = accuracy::render_reference(loaded);
  const Texels gpu = accuracy::render_gpu(device, loaded);
  const auto error = [&](const std::vector<bool>& mask) {
    const accuracy::FogComparison c = accuracy::compare_fog(gpu, ref, mask);
    return std::pair{c.compared_pixels ? c.difference.relative_mean_error : 0.0, c.compared_pixels};
  };
  DemoErrors e;
  e.all = error(std::vector<bool>(size_t(size.width) * size.height, true)).first;
  std::tie(e.fog_only, e.fog_pixels) = error(accuracy::fog_only_pixels(loaded.config.scene, size.width, size.height));
  std::tie(e.surfaces, e.surface_pixels) = error(accuracy::surface_only_pixels(loaded.config.scene, size.width, size.height));
  return e;
}

// The demos table of the file comment, for `configs` (all the demos when empty).
int run_demos(Extent size, std::vector<std::string> configs) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto context = vulkan::Context::create({});
  vulkan::VulkanDevice device(*context);
  if (configs.empty()) {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(VOLGRAPH_SOURCE_DIR) + "/configs")) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("demo_", 0) == 0 && entry.path().extension() == ".json") configs.push_back(entry.path().string());
    }
    std::sort(configs.begin(), configs.end());
  }
  std::printf("bench_fog_sweep demos: each config at %ux%u, frame 0 (linear, composite none) against the reference; relative mean "
              "absolute error over all / fog-only / surface-only pixels, as shipped and like for like; lavapipe (CPU) on %s\n",
              size.width, size.height, device.info().device.c_str());
  std::printf("%-24s %9s %9s %9s | %9s %9s %9s | %s\n", "config", "all px", "fog-only", "surfaces", "all px", "fog-only", "surfaces",
              "pixels (fog, surfaces)");
  for (const std::string& config : configs) {
    LoadedConfig loaded = accuracy::load_linear(config, registry, {.size = size});
    const DemoErrors shipped = demo_errors(device, loaded);
    leave_out_unmodelled_terms(loaded);
    const DemoErrors like = demo_errors(device, loaded);
    std::printf("%-24s %9.4f %9.4f %9.4f | %9.4f %9.4f %9.4f | %zu, %zu\n",
                std::filesystem::path(config).filename().string().c_str(), shipped.all, shipped.fog_only, shipped.surfaces, like.all,
                like.fog_only, like.surfaces, shipped.fog_pixels, shipped.surface_pixels);
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace
}  // namespace volgraph

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  volgraph::Extent size{320, 180, 1};
  const std::string which = argc > 3 ? argv[3] : "froxel";
  if ((argc > 2 && std::sscanf(argv[2], "%ux%u", &size.width, &size.height) != 2) ||
      (which != "froxel" && which != "light_volume" && which != "demos")) {
    std::fprintf(stderr, "usage: bench_fog_sweep [FRAMES] [WxH] [froxel|light_volume|demos]\n");
    return 2;
  }
  try {
    if (which == "demos") return volgraph::run_demos(size, std::vector<std::string>(argv + std::min(argc, 4), argv + argc));
    const volgraph::Sweep sweep = which == "froxel" ? volgraph::Sweep{volgraph::kDemo, volgraph::froxel_settings(), std::nullopt}
                                                    : volgraph::light_volume_sweep();
    return volgraph::run(frames, size, sweep);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_fog_sweep: %s\n", e.what());
    return 1;
  }
}
