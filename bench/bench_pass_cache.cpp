// Benchmark (not a test): what caching opacity_shadow_map saves on demo_fog (Vulkan). The
// pass is cached (PassDecl::cached): its key — the scene's lights and media and the light
// view of shadow_map, which follows the still camera — holds from frame to frame, so from
// frame 2 on it is skipped and its optical depth kept. Each repetition renders FRAMES
// frames with a fresh executor of the graph as loaded (caching on) and of the same graph
// with the pass's decl copied and `cached` off (the pass runs every frame), the two in
// alternating order; prints the median frame wall time (submit to completion, time stamps
// off) over frames 2..FRAMES of all repetitions, each repetition's, and the ratio off/on.
// Fails (exit 1) unless the cached run skipped the pass on every frame after the first and
// the uncached one on none.
//   bench_pass_cache [REPETITIONS] [FRAMES] [WxH]     default 5 repetitions, 8 frames, 320x180
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/device_label.h"
#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

const std::string kConfig = std::string(::volgraph::testing::source_dir()) + "/configs/demo_fog.json";
constexpr const char* kCachedType = "opacity_shadow_map";

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0 : values[values.size() / 2];
}

struct Mode {
  const char* name;
  LoadedConfig config;
  std::unique_ptr<PassDecl> uncached;  // the pass's decl with `cached` off, when off
  std::vector<double> ms;              // frames 2..N of every repetition
  std::vector<double> rep_medians;
};

// Frame wall times of frames 2..frames (ms); throws unless the pass was skipped exactly
// when `cached` says it must be.
std::vector<double> run_frames(rhi::Device& device, const LoadedConfig& c, int frames, bool cached) {
  Executor e(device, c.graph, &c.config.scene, CompileOptions{});
  e.set_gpu_timing(false);
  std::vector<double> ms;
  for (int f = 1; f <= frames; ++f) {
    e.run_frame();
    if (f > 1) ms.push_back(e.frame_wall_ms());
    for (const PassTiming& t : e.timings()) {
      if (t.type == kCachedType && t.cached != (cached && f > 1)) {
        throw std::runtime_error(std::string(kCachedType) + (t.cached ? " skipped" : " ran") + " on frame " + std::to_string(f) +
                                 " with caching " + (cached ? "on" : "off"));
      }
    }
  }
  return ms;
}

int run(int repetitions, int frames, Extent size) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto context = vulkan::Context::create({});
  vulkan::VulkanDevice device(*context);
  Overrides o;
  o.size = size;
  Mode on{"on ", load_config(kConfig, registry, o), nullptr, {}, {}};
  Mode off{"off", load_config(kConfig, registry, o), nullptr, {}, {}};
  bool found = false;
  for (GraphPass& p : off.config.graph.passes) {
    if (p.decl->name != kCachedType) continue;
    if (!p.decl->cached) throw std::runtime_error(std::string(kCachedType) + " is not cached");
    off.uncached = std::make_unique<PassDecl>(*p.decl);
    off.uncached->cached = false;
    p.decl = off.uncached.get();
    found = true;
  }
  if (!found) throw std::runtime_error("demo_fog has no " + std::string(kCachedType));
  for (int r = 0; r < repetitions; ++r) {
    for (Mode* m : r % 2 ? std::vector<Mode*>{&off, &on} : std::vector<Mode*>{&on, &off}) {
      const std::vector<double> ms = run_frames(device, m->config, frames, m == &on);
      m->ms.insert(m->ms.end(), ms.begin(), ms.end());
      m->rep_medians.push_back(median(ms));
    }
  }
  std::printf("bench_pass_cache: demo_fog.json at %ux%u, %d repetitions of %d frames (a fresh executor each), median frame "
              "wall time over frames 2..%d (time stamps off); on %s\n",
              size.width, size.height, repetitions, frames, frames, bench::device_label(device.info().device).c_str());
  for (const Mode* m : {&on, &off}) {
    std::printf("%s cached %s: %8.2f ms   repetitions:", kCachedType, m->name, median(m->ms));
    for (const double v : m->rep_medians) std::printf(" %.2f", v);
    std::printf("\n");
  }
  std::printf("ratio off/on: %8.3f\n", median(off.ms) / median(on.ms));
  return 0;
}

}  // namespace
}  // namespace volgraph

int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const int frames = argc > 2 ? std::max(2, std::atoi(argv[2])) : 8;
  volgraph::Extent size{320, 180, 1};
  if (argc > 3 && std::sscanf(argv[3], "%ux%u", &size.width, &size.height) != 2) {
    std::fprintf(stderr, "usage: bench_pass_cache [REPETITIONS] [FRAMES] [WxH]\n");
    return 2;
  }
  try {
    return volgraph::run(repetitions, frames, size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_pass_cache: %s\n", e.what());
    return 1;
  }
}
