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
  std::vector<PointResult> faster_over_budget;  // faster points whose error is over the budget (why they lost)
  int candidates = 0;                           // points of the chosen device under the budget
};

// The fastest ok point (median frame time) of one device with metric ≤ max_error
// (`metric` a lower-is-better name of metrics.h); nullopt when none is under it.
std::optional<TuneChoice> tune(const std::vector<PointResult>& results, const std::string& metric, double max_error);

// The overlay config's JSON: includes `spec.config` (relative to `overlay_dir`) and
// amends the point's passes. A point of a series with its own graph cannot be an
// overlay (a config cannot drop the graph it includes): the text then says to use
// `--graph FILE` with the flags.
std::string tuned_overlay_json(const SweepSpec& spec, const TuneChoice& choice, const std::string& overlay_dir);
// The flags (--graph, --variant, --set lines) and the figures of the choice, for people.
std::string tuned_summary_text(const SweepSpec& spec, const TuneChoice& choice, const std::string& metric, double max_error);

}  // namespace volgraph::compare
