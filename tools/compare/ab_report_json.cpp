#include "tools/compare/ab_report.h"
#include "tools/compare/figures_json.h"
#include "tools/compare/heatmap.h"

namespace volgraph::compare {
namespace {

Json render_json(const Rendered& render) {
  const std::string stem = report_file_stem(render.label);
  Json out = {{"label", render.label},
              {"setting", render.setting},
              {"command", render.command},
              {"width", render.image.width},
              {"height", render.image.height},
              {"png", stem + ".png"},
              {"pfm", stem + ".pfm"},
              {"seconds", number_json(render.seconds)}};
  out["timing"] = render.timing ? timing_json(*render.timing) : Json(nullptr);
  out["memory"] = render.memory ? memory_json(*render.memory) : Json(nullptr);
  return out;
}

Json comparison_json(const Comparison& comparison, const AbReport& report) {
  const std::string pair = report_file_stem(comparison.test) + "_vs_" + report_file_stem(comparison.against);
  Json masks = Json::array();
  for (const MaskedMetrics& masked : comparison.by_mask) {
    masks.push_back({{"mask", masked.mask}, {"mask_pixels", masked.mask_pixels}, {"metrics", metrics_json(masked.metrics)}});
  }
  const HeatmapRange abs_range = abs_error_range(comparison.abs_error_map);
  Json heatmaps = Json::object();
  if (heatmap_fits(comparison.abs_error_map, report)) {
    heatmaps["abs_error"] = {{"png", "error_" + pair + ".png"}, {"colour_map", "viridis"}, {"min", number_json(abs_range.min)}, {"max", number_json(abs_range.max)}};
  }
  if (heatmap_fits(comparison.flip_map, report)) {
    heatmaps["flip"] = {{"png", "flip_" + pair + ".png"}, {"colour_map", "magma"}, {"min", kFlipRange.min}, {"max", kFlipRange.max}};
  }
  return {{"test", comparison.test}, {"against", comparison.against}, {"by_mask", masks}, {"heatmaps", heatmaps}};
}

}  // namespace

std::string ab_report_json(const AbReport& report) {
  Json renders = Json::array(), comparisons = Json::array();
  for (const Rendered& render : report.renders) renders.push_back(render_json(render));
  for (const Comparison& comparison : report.comparisons) comparisons.push_back(comparison_json(comparison, report));
  const Json out = {{"volgraph_version", report.volgraph_version},
                    {"command_line", report.command_line},
                    {"config", report.config},
                    {"pass", report.pass},
                    {"backend", report.backend},
                    {"device", report.device},
                    {"driver", report.driver},
                    {"device_is_cpu", report.device_is_cpu},
                    {"width", report.width},
                    {"height", report.height},
                    {"frames", report.frames},
                    {"display_exposure", number_json(report_display_exposure(report))},
                    {"non_finite_numbers", "written as the strings \"inf\", \"-inf\", \"nan\""},
                    {"renders", renders},
                    {"comparisons", comparisons},
                    {"notes", report.notes}};
  return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";  // bad UTF-8 in a name → U+FFFD
}

}  // namespace volgraph::compare
