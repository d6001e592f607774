// Benchmark (not a test): what dual-source blending saves the translucency pass (one draw
// a translucent layer — radiance + colour × transmittance — instead of two) on
// demo_stained_glass (Vulkan), sorted and depth_peeling. Each repetition renders FRAMES
// frames with a fresh executor with `glass.dual_source` on and off, the two in
// alternating order; prints the median GPU time of the translucency pass's steps (time
// stamps) over frames 2..FRAMES of all repetitions, each repetition's, and the ratio
// off/on. Fails (exit 1) where the device does not offer dual-source blending (there is
// nothing to compare).
//   bench_dual_source [REPETITIONS] [FRAMES] [WxH]     default 5 repetitions, 6 frames, 640x360
#include <algorithm>
#include <cstdio>
#include <cstdlib>
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

const std::string kDualSourceConfig = std::string(::volgraph::testing::source_dir()) + "/configs/demo_stained_glass.json";

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0 : values[values.size() / 2];
}

struct DrawMode {
  const char* name;
  LoadedConfig config;
  std::vector<double> ms;  // frames 2..N of every repetition
  std::vector<double> rep_medians;
};

// The translucency pass's GPU time (ms, all its steps) on frames 2..frames.
std::vector<double> translucency_ms(rhi::Device& device, const LoadedConfig& c, int frames) {
  Executor e(device, c.graph, &c.config.scene, CompileOptions{});
  std::vector<double> ms;
  for (int f = 1; f <= frames; ++f) {
    e.run_frame();
    double pass_ms = 0;
    for (const PassTiming& t : e.timings()) {
      if (t.type == "translucency") pass_ms += t.gpu_ms;
    }
    if (f > 1) ms.push_back(pass_ms);
  }
  return ms;
}

LoadedConfig with_dual_source(const PassRegistry& registry, Extent size, const std::string& variant, bool on) {
  Overrides o;
  o.size = size;
  o.variants = {"glass=" + variant};
  o.sets = {std::string("glass.dual_source=") + (on ? "true" : "false")};
  return load_config(kDualSourceConfig, registry, o);
}

int run(int repetitions, int frames, Extent size) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto context = vulkan::Context::create({});
  vulkan::VulkanDevice device(*context);
  if (!device.has_dual_source_blending()) throw std::runtime_error(device.info().device + " does not offer dual-source blending");
  if (!device.has_timestamps()) throw std::runtime_error(device.info().device + " has no time stamps");
  std::printf("bench_dual_source: demo_stained_glass.json at %ux%u, %d repetitions of %d frames (a fresh executor each), median "
              "GPU time of the translucency pass over frames 2..%d; on %s\n",
              size.width, size.height, repetitions, frames, frames, bench::device_label(device.info().device).c_str());
  const std::string where = device.info().device.find("llvmpipe") != std::string::npos ? " lavapipe (CPU)" : "";
  for (const char* variant : {"sorted", "depth_peeling"}) {
    DrawMode one{"one draw a layer (dual_source on) ", with_dual_source(registry, size, variant, true), {}, {}};
    DrawMode two{"two draws a layer (dual_source off)", with_dual_source(registry, size, variant, false), {}, {}};
    for (int r = 0; r < repetitions; ++r) {
      for (DrawMode* m : r % 2 ? std::vector<DrawMode*>{&two, &one} : std::vector<DrawMode*>{&one, &two}) {
        const std::vector<double> ms = translucency_ms(device, m->config, frames);
        m->ms.insert(m->ms.end(), ms.begin(), ms.end());
        m->rep_medians.push_back(median_of(ms));
      }
    }
    for (const DrawMode* m : {&one, &two}) {
      std::printf("%-13s %s: %8.3f ms%s   repetitions:", variant, m->name, median_of(m->ms), where.c_str());
      for (const double v : m->rep_medians) std::printf(" %.3f", v);
      std::printf("\n");
    }
    std::printf("%-13s ratio two/one: %8.3f\n", variant, median_of(two.ms) / median_of(one.ms));
  }
  return 0;
}

}  // namespace
}  // namespace volgraph

int main(int argc, char** argv) {
  const int repetitions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const int frames = argc > 2 ? std::max(2, std::atoi(argv[2])) : 6;
  volgraph::Extent size{640, 360, 1};
  if (argc > 3 && std::sscanf(argv[3], "%ux%u", &size.width, &size.height) != 2) {
    std::fprintf(stderr, "usage: bench_dual_source [REPETITIONS] [FRAMES] [WxH]\n");
    return 2;
  }
  try {
    return volgraph::run(repetitions, frames, size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_dual_source: %s\n", e.what());
    return 1;
  }
}
