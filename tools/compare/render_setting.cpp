#include "tools/compare/render_setting.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "graph/diagnostics.h"
#include "graph/execute/executor.h"
#include "reference/atmosphere_reference.h"
#include "reference/clouds.h"
#include "reference/image_render.h"
#include "reference/pixel_masks.h"
#include "reference/renderer.h"
#include "tools/image_io.h"

namespace volgraph::compare {
namespace {

// Per-pass samples of one setting over its timed rounds.
struct Samples {
  std::vector<double> walls;
  std::vector<std::vector<double>> gpu, cpu;  // per pass of the timed frames
  std::vector<PassTiming> passes;             // names and types, from the first timed frame
};

void record_pass_times(Samples& samples, const std::vector<PassTiming>& timings) {
  if (samples.passes.empty()) {
    samples.passes = timings;
    samples.gpu.resize(timings.size());
    samples.cpu.resize(timings.size());
  }
  for (size_t i = 0; i < timings.size() && i < samples.passes.size(); ++i) {
    samples.gpu[i].push_back(timings[i].gpu_ms);
    samples.cpu[i].push_back(timings[i].cpu_ms);
  }
}

TimingSummary summary_of(const Samples& samples, const RunSettings& run, const rhi::Device& device) {
  TimingSummary t;
  t.runs = run.runs;
  t.warmup = run.warmup;
  t.frame_wall_ms = spread_of(samples.walls);
  t.gpu_timestamps = device.has_timestamps();
  t.clock = clock_note(device);
  for (size_t i = 0; i < samples.passes.size(); ++i) {
    t.passes.push_back({samples.passes[i].pass, samples.passes[i].type, spread_of(samples.gpu[i]), spread_of(samples.cpu[i])});
  }
  return t;
}

MemorySummary memory_of(const Plan& plan) {
  return {plan.memory.aliased_bytes, plan.memory.unaliased_bytes, plan.memory.lower_bound_bytes, plan.memory.persistent_bytes,
          uint32_t(plan.order.size()), uint32_t(plan.culled.size())};
}

}  // namespace

std::vector<SettingRun> run_settings(rhi::Device& device, const std::vector<const LoadedConfig*>& settings, const RunSettings& run) {
  std::vector<std::unique_ptr<Executor>> executors;
  std::vector<SettingRun> out(settings.size());
  for (size_t i = 0; i < settings.size(); ++i) {
    executors.push_back(std::make_unique<Executor>(device, settings[i]->graph, &settings[i]->config.scene, run.compile));
    Executor& e = *executors.back();
    for (int f = 0; f < run.frames; ++f) e.run_frame();
    const Texels texels = e.read_output(0);
    out[i].image = rgb_from_rgba(texels.width, texels.height, texels.rgba);
    out[i].memory = memory_of(e.plan());
  }
  for (int f = 0; f < run.warmup; ++f) {
    for (auto& e : executors) e->run_frame();
  }
  std::vector<Samples> samples(settings.size());
  for (int r = 0; r < run.runs; ++r) {
    for (size_t i = 0; i < executors.size(); ++i) {
      Executor& e = *executors[i];
      e.set_gpu_timing(false);
      e.run_frame();
      samples[i].walls.push_back(e.frame_wall_ms());
      e.set_gpu_timing(true);
      e.run_frame();
      record_pass_times(samples[i], e.timings());
    }
  }
  for (size_t i = 0; i < settings.size(); ++i) out[i].timing = summary_of(samples[i], run, device);
  return out;
}

bool device_is_cpu(const rhi::Device& device) { return device.info().device.find("llvmpipe") != std::string::npos; }

std::string clock_note(const rhi::Device& device) {
  std::string note;
  if (device_is_cpu(device)) {
    note = "lavapipe (CPU): the GPU is this CPU, so every time is CPU time; its time stamps do not bracket compute "
           "dispatches reliably, the frame wall time (submit to completion) does. ";
  }
  if (!device.has_timestamps()) note += "The device has no time stamps: per-pass gpu_ms are 0, cpu_ms (recording) are measured. ";
  note += "Frame wall time: submit to completion of a frame with time stamps off.";
  return note;
}

RgbImage render_reference(const LoadedConfig& loaded, const ReferenceSettings& settings) {
  reference::IntegrationSettings integration;
  integration.relative_tolerance = settings.tolerance;
  // The config's cloud_noise sizes and cloud_march parameters, as `volgraph reference` takes them.
  integration.clouds = reference::cloud_reference_settings(loaded.graph, loaded.params);
  if (settings.refracted) {
    integration.translucency = reference::TranslucencyMode::refracted;
    integration.directional_environment = true;
  }
  reference::AtmosphereReferenceSettings atmosphere;
  atmosphere.samples = settings.atmosphere_paths;
  const reference::Renderer renderer(loaded.config.scene, integration, atmosphere);
  const Extent size = loaded.config.output_size;
  const reference::ReferenceImage image = reference::render_image(
      renderer, {.width = size.width, .height = size.height, .samples_per_axis = settings.samples_per_axis, .threads = settings.threads});
  RgbImage out{image.width, image.height, std::vector<float>(image.rgb.size())};
  for (size_t i = 0; i < image.rgb.size(); ++i) out.rgb[i] = float(image.rgb[i]);
  return out;
}

RgbImage read_reference_image(const std::string& path, uint32_t width, uint32_t height, const std::string& flag) {
  const Where where{"<command line>", flag + " " + path, 0};
  if (image_format_for(path) != ImageFormat::pfm) throw ConfigError({{where, "a reference image must be a .pfm file (linear float)"}});
  const Image image = read_pfm(path);
  if (image.width != width || image.height != height) {
    throw ConfigError({{where, "the reference is " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                   "; expected the comparison's size, " + std::to_string(width) + "x" + std::to_string(height)}});
  }
  RgbImage rgb = rgb_from_rgba(image.width, image.height, image.rgba);
  // A reference is the truth the figures are measured against: a NaN or Inf in it is bad
  // input, not a pixel to leave out (all of them left out would score a perfect match).
  const auto bad = std::find_if(rgb.rgb.begin(), rgb.rgb.end(), [](float v) { return !std::isfinite(v); });
  if (bad != rgb.rgb.end()) {
    const size_t pixel = size_t(bad - rgb.rgb.begin()) / 3;
    const size_t count = size_t(std::count_if(rgb.rgb.begin(), rgb.rgb.end(), [](float v) { return !std::isfinite(v); }));
    throw ConfigError({{where, std::to_string(count) + " non-finite value(s) (NaN or Inf), the first at pixel (" + std::to_string(pixel % width) +
                                   ", " + std::to_string(pixel / width) + "); expected a reference with every value finite"}});
  }
  return rgb;
}

const std::vector<std::string>& mask_names() {
  static const std::vector<std::string> names{"all", "fog_only", "surfaces"};
  return names;
}

PixelMask mask_named(const std::string& name, const Scene& scene, uint32_t width, uint32_t height) {
  if (name == "fog_only") return reference::fog_only_pixels(scene, width, height);
  if (name == "surfaces") return reference::surface_only_pixels(scene, width, height);
  return {};
}

std::string mask_title(const std::string& name) {
  if (name == "fog_only") return "fog-only pixels";
  if (name == "surfaces") return "surface pixels";
  return "all pixels";
}

}  // namespace volgraph::compare
