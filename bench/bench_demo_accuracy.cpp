// Benchmark (not a test): every demo against the CPU reference. Each configs/demo_*.json
// (or the CONFIGs named), its first frame against the reference of the same size —
// relative mean error over all pixels, over the fog-only pixels and over the
// surface-only pixels (the pixel and its 3×3 neighbourhood all see a surface), the metric
// of tests/support/fog_accuracy.h — as shipped, and like for like: the terms the
// reference does not model left out on both sides (every pass's `ambient` set to 0; the
// camera's far plane brought to where the technique's media end, the froxel grid's `far`
// or raymarch_fog's `max_distance`). Run time against error over quality settings is
// `volgraph sweep` (configs/sweeps/).
//   bench_demo_accuracy [WxH] [CONFIG...]      default 96x54, every demo
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <tuple>
#include <string>
#include <utility>
#include <vector>

#include "bench/device_label.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "passes/passes.h"
#include "tests/support/fog_accuracy.h"
#include "tests/support/source_dir.h"

namespace volgraph {
namespace {

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
    for (const auto& entry : std::filesystem::directory_iterator(std::string(::volgraph::testing::source_dir()) + "/configs")) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("demo_", 0) == 0 && entry.path().extension() == ".json") configs.push_back(entry.path().string());
    }
    std::sort(configs.begin(), configs.end());
  }
  std::printf("bench_demo_accuracy: each config at %ux%u, frame 0 (linear, composite none) against the reference; relative mean "
              "absolute error over all / fog-only / surface-only pixels, as shipped and like for like; on %s\n",
              size.width, size.height, bench::device_label(device.info().device).c_str());
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
  volgraph::Extent size{96, 54, 1};
  int first_config = 1;
  if (argc > 1 && std::sscanf(argv[1], "%ux%u", &size.width, &size.height) == 2) first_config = 2;
  else if (argc > 1 && std::string(argv[1]).find(".json") == std::string::npos) {
    std::fprintf(stderr, "usage: bench_demo_accuracy [WxH] [CONFIG...]\n");
    return 2;
  }
  try {
    return volgraph::run_demos(size, std::vector<std::string>(argv + first_config, argv + argc));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_demo_accuracy: %s\n", e.what());
    return 1;
  }
}
