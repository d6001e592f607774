// One setting of a comparison rendered and timed on a device, and the reference it is
// measured against: what `volgraph ab` and `volgraph sweep` share.
//
// A setting's image is its graph's first output after `frames` frames (frame 0 samples
// froxels at their centres; temporal passes need more), with every composite linear
// (passes/linear_output.h). Then `warmup` frames, then `runs` rounds of two frames: one
// with GPU time stamps off (its frame wall time, submit to completion, is the figure a
// frame costs unprofiled) and one with them on (the per-pass times). Several settings
// timed together take their rounds in turn, so a change in the machine's load falls on
// all of them alike.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "graph/config/config.h"
#include "graph/rhi/rhi.h"
#include "tools/compare/ab_report.h"
#include "tools/compare/rgb_image.h"
#include "tools/compare/timing.h"

namespace volgraph::compare {

struct RunSettings {
  int frames = 1;  // frames before the compared image
  int warmup = 1;  // frames after it, untimed
  int runs = 5;    // timed rounds
  CompileOptions compile;
};

struct SettingRun {
  RgbImage image;
  TimingSummary timing;
  MemorySummary memory;
};

// Renders and times every setting on `device` (their rounds interleaved).
std::vector<SettingRun> run_settings(rhi::Device& device, const std::vector<const LoadedConfig*>& settings, const RunSettings& run);

// What the times measure on this device, for the reports: "lavapipe (CPU): …" on
// Mesa's CPU driver, the time stamps' absence where the device has none.
std::string clock_note(const rhi::Device& device);
bool device_is_cpu(const rhi::Device& device);

// The CPU reference of the config's scene at its output size (reference/), linear.
struct ReferenceSettings {
  unsigned threads = 0;
  double tolerance = 1e-5;
  uint32_t samples_per_axis = 1;
  uint32_t atmosphere_paths = 64;  // the atmosphere's Monte Carlo paths a ray (orders ≥ 2)
  // Solids' two interfaces traced and reflections toward the mirrored ray (reference/renderer.h's
  // refracted mode, IntegrationSettings::directional_environment); false: straight layers.
  bool refracted = false;
};
RgbImage render_reference(const LoadedConfig& loaded, const ReferenceSettings& settings);

// A linear image from a file (.pfm); ConfigError naming `flag` when it cannot be read
// or its size is not `width`×`height`.
RgbImage read_reference_image(const std::string& path, uint32_t width, uint32_t height, const std::string& flag);

// The masks' names, as specs and reports use them: "all", "fog_only", "surfaces".
const std::vector<std::string>& mask_names();

// A pixel mask by name: "all" (every pixel: an empty mask), "fog_only", "surfaces"
// (reference/pixel_masks.h), for the scene at width×height.
PixelMask mask_named(const std::string& name, const Scene& scene, uint32_t width, uint32_t height);
// "all pixels", "fog-only pixels", "surface pixels".
std::string mask_title(const std::string& name);

}  // namespace volgraph::compare
