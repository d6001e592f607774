// The human side of a sweep's aggregates: the plot of frame time against error (SVG,
// one panel a device, each series its colour, the Pareto front joined) and report.html
// (self-contained: the plot inline, a table a device, the failed points).
#pragma once

#include <string>
#include <vector>

#include "tools/compare/sweep_results.h"

namespace volgraph::compare {

// `ordered` as write_aggregates orders it, with the front marked (mark_pareto). Time
// (median frame ms) on x, the spec's metric on y; an axis is logarithmic when its values
// are positive and span more than 10×. Each point has a <title> (shown on hover).
std::string pareto_svg(const SweepSpec& spec, const std::vector<PointResult>& ordered);
std::string sweep_report_html(const SweepSpec& spec, const std::vector<PointResult>& ordered, const std::string& svg);

}  // namespace volgraph::compare
