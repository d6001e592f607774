// A sweep spec (configs/sweeps/*.json): a config, the settings to render it at, the
// reference and the metric. `volgraph sweep` renders every point the spec expands to.
//
//   {
//     "description": "…",
//     "config": "../demo_fog.json",          (relative to the spec's folder)
//     "size": [160, 90], "runs": 5, "warmup": 1, "frames": 1, "backend": "vulkan",
//     "reference": "cpu",                    (or an image file: .pfm / .exr, linear)
//     "metric": "rel_rmse",                  (metrics.h metric_names(); the error of the front)
//     "mask": "fog_only",                    (all | fog_only | surfaces)
//     "series": [
//       { "name": "wronski",
//         "graph": "../graphs/raymarch_fog.json",      optional: the config's graph replaced by this file's
//         "set":  { "fog_integral": "wronski", "sun_shadow.resolution": 2048 },
//         "vary": { "fog_media.slices": [16, 32, 64, 128],
//                   "fog_integral": ["wronski", "hillaire"],
//                   "fog_march.steps": { "from": 16, "to": 256, "times": 2 },
//                   "fog_media.far": { "from": 20, "to": 60, "step": 20 } } }
//     ]
//   }
// A key "PASS.PARAM" sets a parameter (its value as JSON, as --set takes it); a key
// "PASS" picks a variant (--variant). A series' points are the cartesian product of its
// "vary" lists, in the order written (the last key varies fastest), each with "set".
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "graph/config/config.h"

namespace volgraph::compare {

struct SweepPoint {
  std::string id;      // stable across runs and machines: 12 hex digits of a hash of series, graph and settings
  std::string series;
  std::string label;   // "fog_media.slices=64, fog_integral=hillaire" (the varied settings)
  std::string graph;   // resolved path of the series' graph file, "" for the config's own
  std::vector<std::pair<std::string, std::string>> settings;  // every key (set and vary) → its JSON text, in order
  Overrides overrides;  // sets and variants as the loader takes them (no size)
};

struct SweepSpec {
  std::string file;     // the spec as named
  std::string description;
  std::string config;   // resolved path
  Extent size{160, 90, 1};
  int runs = 5, warmup = 1, frames = 1;
  std::string backend = "vulkan";
  std::string reference = "cpu";  // "cpu" or a resolved image path
  std::string metric = "rel_rmse";
  std::string mask = "all";
  std::vector<SweepPoint> points;  // expanded, in spec order; ids unique
};

// Reads and checks a spec. Throws ConfigError (file, JSON pointer, line, expectation) for
// anything wrong in it, including a point whose settings the config refuses (each point
// is loaded once against `registry`, the error placed at the series that makes it).
SweepSpec read_sweep_spec(const std::string& path, const PassRegistry& registry);

}  // namespace volgraph::compare
