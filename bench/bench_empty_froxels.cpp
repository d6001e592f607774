// Benchmark (not a test): what skipping empty froxels saves. A medium confined to a local
// volume — configs/tests/oracle_fog_sphere.json, one fog sphere (radius 2 m) under a
// point light — leaves most froxels of the grid empty; froxel_scatter skips the light
// loop for a froxel without scattering (one texel fetch and a store remain). Renders the
// froxel chain with `skip_empty` on and off, frame after frame in turn (so a change in
// the machine's load falls on both), with volumetric self-shadowing by a march of
// `shadow_steps` so that the light loop costs what it would in a scene with shadows;
// prints the fraction of empty froxels, the median frame wall time (submit to
// completion, time stamps off) of each and their ratio.
//   bench_empty_froxels [FRAMES] [WxH] [SHADOW_STEPS]     default 9 frames, 320x180, 32 steps
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/device_label.h"
#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/passes.h"
#include "tests/support/fog_accuracy.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

const std::string kScene = std::string(::volgraph::testing::source_dir()) + "/configs/tests/oracle_fog_sphere.json";

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0 : values[values.size() / 2];
}

LoadedConfig load(const PassRegistry& registry, Extent size, int shadow_steps, bool skip_empty) {
  Overrides o;
  o.size = size;
  o.sets = {"fog_light.shadow_steps=" + std::to_string(shadow_steps), std::string("fog_light.skip_empty=") + (skip_empty ? "true" : "false")};
  return accuracy::load_linear(kScene, registry, o);
}

// The media_scattering volume kept as a graph output (not aliased: it can be read back).
uint32_t keep_media_scattering(Graph& graph) {
  for (uint32_t r = 0; r < graph.resources.size(); ++r) {
    if (graph.resources[r].desc.name != "fog_media.media_scattering") continue;
    graph.outputs.push_back({r, uint32_t(graph.resources[r].version_writers.size() - 1)});
    return r;
  }
  throw std::runtime_error("the scene's graph has no fog_media.media_scattering");
}

// The share of froxels froxel_voxelize leaves without scattering.
double empty_fraction(Executor& executor, uint32_t media_scattering) {
  const Texels t = executor.read_texture(media_scattering);
  size_t empty = 0;
  for (size_t k = 0; k < t.rgba.size(); k += 4) empty += t.rgba[k] == 0 && t.rgba[k + 1] == 0 && t.rgba[k + 2] == 0;
  return double(empty) / double(t.rgba.size() / 4);
}

int run(int frames, Extent size, int shadow_steps) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto context = vulkan::Context::create({});
  vulkan::VulkanDevice device(*context);
  LoadedConfig skipping = load(registry, size, shadow_steps, true);
  const uint32_t media_scattering = keep_media_scattering(skipping.graph);
  const LoadedConfig lighting_all = load(registry, size, shadow_steps, false);
  Executor skip(device, skipping.graph, &skipping.config.scene, CompileOptions{});
  Executor all(device, lighting_all.graph, &lighting_all.config.scene, CompileOptions{});
  std::vector<double> skip_ms, all_ms;
  for (Executor* e : {&skip, &all}) {
    e->set_gpu_timing(false);
    e->run_frame();  // warm-up
  }
  for (int f = 0; f < frames; ++f) {
    skip.run_frame();
    skip_ms.push_back(skip.frame_wall_ms());
    all.run_frame();
    all_ms.push_back(all.frame_wall_ms());
  }
  const double empty = empty_fraction(skip, media_scattering);
  std::printf("bench_empty_froxels: oracle_fog_sphere.json at %ux%u, froxel chain with shadow_steps %d, %d frames after one "
              "warm-up, median frame wall time; on %s\n",
              size.width, size.height, shadow_steps, frames, bench::device_label(device.info().device).c_str());
  std::printf("empty froxels: %.1f %%\n", 100 * empty);
  std::printf("skip_empty on : %8.2f ms\nskip_empty off: %8.2f ms\nratio off/on  : %8.2f\n", median(skip_ms), median(all_ms),
              median(all_ms) / median(skip_ms));
  return 0;
}

}  // namespace
}  // namespace volgraph

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
  volgraph::Extent size{320, 180, 1};
  if (argc > 2 && std::sscanf(argv[2], "%ux%u", &size.width, &size.height) != 2) {
    std::fprintf(stderr, "usage: bench_empty_froxels [FRAMES] [WxH] [SHADOW_STEPS]\n");
    return 2;
  }
  const int shadow_steps = argc > 3 ? std::max(0, std::atoi(argv[3])) : 32;
  try {
    return volgraph::run(frames, size, shadow_steps);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_empty_froxels: %s\n", e.what());
    return 1;
  }
}
