// A sweep spec (configs/sweeps/*.json): a config, the settings to render it at, the
// reference and the metric. `volgraph sweep` renders every point the spec expands to.
//
//   {
//     "description": "…",
//     "config": "../demo_fog.json",          (relative to the spec's folder)
//     "size": [160, 90], "runs": 5, "warmup": 1, "frames": 1, "backend": "vulkan",
//     "reference": "cpu",                    (or an image file: .pfm / .exr, linear)
//     "reference_mode": "straight",          (the CPU reference's translucency: straight | refracted)
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
// A key "PASS.PARAM" sets a parameter (its value as JSON, as --set takes it: true/false,
// a number, a string or [x, y, z]); a key "PASS" picks a variant (--variant; its value a
// variant's name). A series' points are the cartesian product of its "vary" lists, in
// the order written (the last key varies fastest), each with "set"; a series without
// "vary" is one point. A key is either set or varied, never both. The key "frames" (1…1000)
// sets the point's frame count in place of the spec's (SweepPoint::frames: a temporal
// technique's accumulation); in a spec no pass can go by that name.
//
// Keys and ranges: "config" and "series" are required; "size" [1…16384, 1…16384]
// (default [160, 90]), "runs" 1…1000 (5), "warmup" 0…100 (1), "frames" 1…1000 (1),
// "backend" vulkan | webgpu, "reference" "cpu" or an existing .pfm / .exr (relative to
// the spec's folder), "reference_mode" straight (the translucency pass's one-interface
// layers, the default) | refracted (solids' two interfaces traced, reflections toward the
// mirrored ray: the truth refraction and environment techniques are measured against), "metric" one of metric_names() (rel_rmse), "mask" all | fog_only |
// surfaces (all). Series: "name" (required, unique), "graph" (an existing file), "set"
// and "vary" objects. A "vary" value is a non-empty array of distinct values, or a range
// of a parameter (or of "frames", integers):
//   {"from": a, "to": b, "times": t}   a, a·t, a·t², … ≤ b   (a > 0, t > 1)
//   {"from": a, "to": b, "step": s}    a, a + s, a + 2s, … ≤ b (s > 0; b included when
//                                      (b − a)/s is within 1e-9 of a whole number)
// A range of integers (a and t, or a and s, written as integers) gives integers; other
// ranges give their values rounded to 12 significant digits (0.1 + 2 × 0.1 is 0.3).
// A spec expands to at most kMaxSweepPoints points (a range to at most as many values).
// No two points of a spec render the same (graph, frames and settings in any order alike).
//
// Every problem is one diagnostic (file, JSON pointer, line, expectation), all thrown
// together as a ConfigError. A point the config refuses is reported with the loader's
// message at the series' key that sets it (the loader names the flag: at the listed
// value that makes it, at the key when several values do) or else at the series.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "graph/config/config.h"

namespace volgraph::compare {

// Most points one spec may expand to.
constexpr size_t kMaxSweepPoints = 10000;

struct SweepPoint {
  std::string id;      // stable across runs and machines: sweep_point_id(series, graph as written, settings)
  std::string series;
  std::string label;   // "fog_media.slices=64, fog_integral=hillaire": the varied settings, strings unquoted;
                       // the series name when nothing varies
  std::string graph;   // resolved path of the series' graph file, "" for the config's own
  std::vector<std::pair<std::string, std::string>> settings;  // every key (set, then vary) → its compact JSON text
                                                              // (a variant's name quoted: "\"hillaire\""), in order
  Overrides overrides;  // sets and variants as the loader takes them (no size)
  int frames = 1;       // frames rendered before the image is measured: the point's "frames" setting, else the spec's
};

struct SweepSpec {
  std::string file;     // the spec as named
  std::string description;
  std::string config;   // resolved path
  Extent size{160, 90, 1};
  int runs = 5, warmup = 1, frames = 1;
  std::string backend = "vulkan";
  std::string reference = "cpu";  // "cpu" or a resolved image path
  std::string reference_mode = "straight";  // the CPU reference's: straight | refracted
  std::string metric = "rel_rmse";
  std::string mask = "all";
  std::vector<SweepPoint> points;  // expanded, in spec order; ids unique
};

// Reads and checks a spec. Throws ConfigError (file, JSON pointer, line, expectation) for
// anything wrong in it, including a point whose settings the config refuses (each point
// is loaded once against `registry`, the error placed at the series that makes it).
SweepSpec read_sweep_spec(const std::string& path, const PassRegistry& registry);

// A point's id: FNV-1a 64 (Fowler, Noll, Vo) of the bytes
//   series "\n" graph-as-written-in-the-spec ("" for none) "\n" then KEY "=" JSON-TEXT "\n" per setting,
// its low 48 bits as 12 lower-case hex digits. Depends on nothing but the spec's text.
std::string sweep_point_id(const std::string& series, const std::string& graph_as_written,
                           const std::vector<std::pair<std::string, std::string>>& settings);

}  // namespace volgraph::compare
