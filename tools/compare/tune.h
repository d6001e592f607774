// `volgraph tune`: the fastest point of a sweep whose error stays under a budget, as a
// config overlay (a config that includes the swept one and sets the point's variants
// and parameters) and as the --set / --variant flags, with the figures that justify it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tools/compare/sweep_results.h"
#include "tools/compare/sweep_spec.h"

namespace volgraph::compare {

struct TuneChoice {
  PointResult chosen;
  std::vector<PointResult> faster_over_budget;  // faster points whose error is over the budget (why they lost), fastest first
  int candidates = 0;                           // points of the chosen device under the budget
  int points = 0;                               // ok points of the chosen device
  std::vector<std::string> other_devices;       // devices of the results left out (tuning is over one device)
  std::string metric;                           // the budget tune was given: metric ≤ max_error
  double max_error = 0;
};

// The fastest ok point (timing.frame_wall_ms.median; the first in `results` on a tie) with
// metric_value(metrics, metric) ≤ max_error (at the budget counts as under), over one
// device: the device of the first ok result; the others are named in other_devices (tune
// each device's results apart to compare them). A point whose image held NaN or Inf
// values (metrics.nan_values, inf_values), or whose figure is NaN, is over any budget.
// nullopt when no point is under it. Throws std::invalid_argument when `metric` is not a
// lower-is-better name of metrics.h (psnr and ssim are higher-is-better) or max_error is NaN.
std::optional<TuneChoice> tune(const std::vector<PointResult>& results, const std::string& metric, double max_error);

// Whether the choice can be written as an overlay: not when its series has its own graph
// (a config cannot drop the graph it includes; the summary's flags with --graph FILE do it).
bool tuned_overlay_possible(const TuneChoice& choice);
// The overlay config's JSON: {"description": "… tuned by volgraph tune: METRIC ≤ X, …",
// "include": spec.config relative to `overlay_dir`, "graph": {"passes": [{"name": P,
// "variant": V, "params": {…}}, …]}}, one entry a pass in the order the settings first name
// it. When !tuned_overlay_possible(choice): a document that is not a config (the loader
// refuses its key "render_with", exit 2) holding the command that renders the point,
// `volgraph render CONFIG --graph FILE --variant … --set …`, and the figures.
std::string tuned_overlay_json(const SweepSpec& spec, const TuneChoice& choice, const std::string& overlay_dir);
// For people: the flags, one a line (--graph FILE when the series has one, --variant
// PASS=NAME, --set PASS.PARAM=VALUE, shell-quoted where needed), then the chosen point's
// figures (median [min–max] frame time, the error against the budget, the device) and
// the faster points that lost, with their errors.
std::string tuned_summary_text(const SweepSpec& spec, const TuneChoice& choice, const std::string& metric, double max_error);

}  // namespace volgraph::compare
