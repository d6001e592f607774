// Benchmark (not a test): run time against error. Each fog technique over its quality
// settings on configs/demo_fog.json, rendered on Vulkan (lavapipe) frame after frame —
// the median frame wall time (submit to completion, GPU time stamps off) — and its
// first frame compared with the CPU reference of the same scene and size (computed
// once; linear outputs, composite forced to `none`; fog-only pixels and metric of
// tests/support/fog_accuracy.h). Settings take turns frame by frame, so a change in the
// machine's load falls on all of them alike. Prints the table with the ratio to the
// fastest setting and marks the Pareto-optimal rows (no other row is both faster and
// closer).
// Two changes make the demo comparable with the reference, applied to both renders:
// the fog ball's edge fade is removed (the reference's volumes are hard-edged), and the
// camera's far plane is brought to the froxel grid's far end (the reference integrates
// the media to the far plane, the grid stops at its `far`).
//   bench_fog_sweep [FRAMES] [WxH]     default 5 frames at 320x180, after one warm-up frame
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/passes.h"
#include "tests/support/fog_accuracy.h"

namespace volgraph {
namespace {

const std::string kDemo = std::string(VOLGRAPH_SOURCE_DIR) + "/configs/demo_fog.json";

// One row of the sweep: a technique at one quality setting, as overrides of the demo.
struct Setting {
  std::string technique;
  std::string label;
  Overrides overrides;
};

struct Row {
  Setting setting;
  double frame_ms = 0;
  accuracy::FogComparison fog_only;  // the fog-only pixels (the figure the front is taken on)
  accuracy::FogComparison all;       // every pixel, surfaces too (differences outside the technique included)
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
        out.push_back({"froxel", std::string(integration) + ", " + std::to_string(slices) + " slices, shadow " + std::to_string(shadow), o});
      }
    }
  }
  return out;
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

// The two changes of the file comment.
void make_comparable(LoadedConfig& loaded) {
  for (MediumVolume& volume : loaded.config.scene.media.volumes) volume.noise.edge_fade = 0;
  loaded.config.scene.camera.far = grid_far(loaded);
}

LoadedConfig load_setting(const PassRegistry& registry, Extent size, Overrides overrides) {
  overrides.size = size;
  LoadedConfig loaded = accuracy::load_linear(kDemo, registry, overrides);
  make_comparable(loaded);
  return loaded;
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
                         const reference::ReferenceImage& ref, const std::vector<bool>& fog_only, int frames) {
  std::vector<Row> rows;
  std::vector<Running> running;
  for (size_t i = 0; i < settings.size(); ++i) {
    running.push_back({std::make_unique<Executor>(device, configs[i].graph, &configs[i].config.scene, CompileOptions{}), {}});
    running.back().executor->set_gpu_timing(false);
    running.back().executor->run_frame();
    const Texels first = running.back().executor->read_output(0);
    rows.push_back({settings[i], 0, accuracy::compare_fog(first, ref, fog_only),
                    accuracy::compare_fog(first, ref, std::vector<bool>(fog_only.size(), true))});
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
  std::printf("%-10s %-36s %10s %8s %12s %12s %s\n", "technique", "setting", "frame ms", "ratio", "error", "(all px)", "front");
  for (const Row& r : rows) {
    std::printf("%-10s %-36s %10.2f %8.2f %12.4f %12.4f %s\n", r.setting.technique.c_str(), r.setting.label.c_str(), r.frame_ms,
                r.frame_ms / fastest, r.fog_only.difference.relative_mean_error, r.all.difference.relative_mean_error,
                r.pareto ? "*" : "");
  }
}

int run(int frames, Extent size) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto context = vulkan::Context::create({});
  vulkan::VulkanDevice device(*context);
  std::printf("bench_fog_sweep: configs/demo_fog.json at %ux%u, %d frames after one warm-up, median frame wall time; "
              "lavapipe (CPU): its \"GPU\" is this CPU (%s)\n",
              size.width, size.height, frames, device.info().device.c_str());
  const std::vector<Setting> settings = froxel_settings();
  const LoadedConfig base = load_setting(registry, size, settings.front().overrides);
  const reference::ReferenceImage ref = accuracy::render_reference(base);
  const std::vector<bool> fog_only = accuracy::fog_only_pixels(base.config.scene, size.width, size.height);
  std::vector<LoadedConfig> configs;
  for (const Setting& setting : settings) configs.push_back(load_setting(registry, size, setting.overrides));
  std::vector<Row> rows = measure(device, configs, settings, ref, fog_only, frames);
  mark_pareto(rows);
  print(rows, rows.front().fog_only);
  return 0;
}

}  // namespace
}  // namespace volgraph

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  volgraph::Extent size{320, 180, 1};
  if (argc > 2 && std::sscanf(argv[2], "%ux%u", &size.width, &size.height) != 2) {
    std::fprintf(stderr, "usage: bench_fog_sweep [FRAMES] [WxH]\n");
    return 2;
  }
  try {
    return volgraph::run(frames, size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_fog_sweep: %s\n", e.what());
    return 1;
  }
}
