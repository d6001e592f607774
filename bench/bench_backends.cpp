// Benchmark (not a test): the demo configs rendered frame after frame on Vulkan and on
// WebGPU (Dawn), printing per pass the median time of each backend — GPU time stamps
// where the device has them, else CPU recording time, said so — the median frame wall
// time (submit to completion) and the WebGPU / Vulkan ratio.
//   bench_backends [FRAMES] [WxH]     default 7 frames at 640x360, after one warm-up frame
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "bench/device_label.h"
#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "graph/rhi/webgpu/webgpu_device.h"
#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

const char* const kDemos[] = {"demo_primitives.json", "demo_point_lights.json", "demo_helmet.json"};

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Median milliseconds per pass (in plan order) and of the frame's wall time.
struct Measured {
  std::vector<std::string> passes;
  std::vector<double> pass_ms;
  double frame_ms = 0;
  bool gpu_timestamps = false;
  std::string device;
};

Measured measure(rhi::Device& device, const LoadedConfig& c, int frames) {
  Executor executor(device, c.graph, &c.config.scene, {});
  executor.run_frame();  // warm-up: pipelines, uploads
  std::vector<std::vector<double>> per_pass;
  std::vector<double> walls;
  for (int f = 0; f < frames; ++f) {
    executor.run_frame();
    const std::vector<PassTiming>& t = executor.timings();
    per_pass.resize(t.size());
    for (size_t i = 0; i < t.size(); ++i) per_pass[i].push_back(device.has_timestamps() ? t[i].gpu_ms : t[i].cpu_ms);
    walls.push_back(executor.frame_wall_ms());
  }
  Measured m{{}, {}, median(walls), device.has_timestamps(), device.info().device};
  for (size_t i = 0; i < per_pass.size(); ++i) {
    m.passes.push_back(executor.timings()[i].pass + " (" + executor.timings()[i].type + ")");
    m.pass_ms.push_back(median(per_pass[i]));
  }
  return m;
}

std::string timing_kind(const Measured& m) { return m.gpu_timestamps ? "GPU time stamps" : "CPU recording (no time stamps)"; }

void print(const std::string& config, const Measured& vulkan, const Measured& webgpu) {
  std::printf("\n%s — %s\n", config.c_str(), bench::device_label(vulkan.device).c_str());
  std::printf("  per pass: vulkan %s, webgpu %s; medians in ms\n", timing_kind(vulkan).c_str(), timing_kind(webgpu).c_str());
  std::printf("  %-32s %10s %10s %8s\n", "pass", "vulkan", "webgpu", "ratio");
  for (size_t i = 0; i < vulkan.passes.size() && i < webgpu.pass_ms.size(); ++i) {
    const double ratio = vulkan.pass_ms[i] > 0 ? webgpu.pass_ms[i] / vulkan.pass_ms[i] : 0;
    std::printf("  %-32s %10.3f %10.3f %8.2f\n", vulkan.passes[i].c_str(), vulkan.pass_ms[i], webgpu.pass_ms[i], ratio);
  }
  std::printf("  %-32s %10.3f %10.3f %8.2f\n", "frame wall (submit → done)", vulkan.frame_ms, webgpu.frame_ms,
              vulkan.frame_ms > 0 ? webgpu.frame_ms / vulkan.frame_ms : 0);
}

int run(int frames, Extent size) {
  PassRegistry registry;
  register_builtin_passes(registry);
  auto context = vulkan::Context::create({});
  vulkan::VulkanDevice vulkan_device(*context);
  const auto webgpu_device = webgpu::WebGpuDevice::create({.errors_throw = true});
  std::printf("bench_backends: %d frames (after one warm-up) at %ux%u\n", frames, size.width, size.height);
  for (const char* demo : kDemos) {
    Overrides o;
    o.size = size;
    const LoadedConfig c = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/" + demo, registry, o);
    const Measured vulkan = measure(vulkan_device, c, frames);
    const Measured webgpu = measure(*webgpu_device, c, frames);
    print(demo, vulkan, webgpu);
  }
  return 0;
}

}  // namespace
}  // namespace volgraph

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  volgraph::Extent size{640, 360, 1};
  if (argc > 2 && std::sscanf(argv[2], "%ux%u", &size.width, &size.height) != 2) {
    std::fprintf(stderr, "usage: bench_backends [FRAMES] [WxH]\n");
    return 2;
  }
  try {
    return volgraph::run(frames, size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_backends: %s\n", e.what());
    return 1;
  }
}
