#include <cmath>
#include <nlohmann/json.hpp>

#include "tools/compare/ab_report.h"
#include "tools/compare/heatmap.h"

namespace volgraph::compare {
namespace {

using Json = nlohmann::ordered_json;

// ab_report.h: a non-finite number is written as "inf", "-inf" or "nan".
Json number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

Json spread_json(const Spread& spread) {
  return {{"median", number(spread.median)}, {"min", number(spread.min)}, {"max", number(spread.max)}, {"runs", spread.runs}};
}

Json timing_json(const TimingSummary& timing) {
  Json passes = Json::array();
  for (const PassTimes& pass : timing.passes) {
    passes.push_back({{"pass", pass.pass}, {"type", pass.type}, {"gpu_ms", spread_json(pass.gpu_ms)}, {"cpu_ms", spread_json(pass.cpu_ms)}});
  }
  return {{"runs", timing.runs},
          {"warmup", timing.warmup},
          {"gpu_timestamps", timing.gpu_timestamps},
          {"clock", timing.clock},
          {"frame_wall_ms", spread_json(timing.frame_wall_ms)},
          {"passes", passes}};
}

Json memory_json(const MemorySummary& memory) {
  return {{"aliased_bytes", memory.aliased_bytes},         {"unaliased_bytes", memory.unaliased_bytes},
          {"lower_bound_bytes", memory.lower_bound_bytes}, {"persistent_bytes", memory.persistent_bytes},
          {"passes_run", memory.passes_run},               {"passes_culled", memory.passes_culled}};
}

Json render_json(const Rendered& render) {
  const std::string stem = report_file_stem(render.label);
  Json out = {{"label", render.label},
              {"setting", render.setting},
              {"command", render.command},
              {"width", render.image.width},
              {"height", render.image.height},
              {"png", stem + ".png"},
              {"pfm", stem + ".pfm"},
              {"seconds", number(render.seconds)}};
  out["timing"] = render.timing ? timing_json(*render.timing) : Json(nullptr);
  out["memory"] = render.memory ? memory_json(*render.memory) : Json(nullptr);
  return out;
}

Json metrics_json(const ErrorMetrics& m) {
  return {{"compared_pixels", m.compared_pixels}, {"nan_values", m.nan_values},
          {"inf_values", m.inf_values},           {"rmse", number(m.rmse)},
          {"relative_rmse", number(m.relative_rmse)}, {"psnr_db", number(m.psnr_db)},
          {"ssim", number(m.ssim)},               {"flip", number(m.flip)},
          {"max_abs_error", number(m.max_abs_error)}, {"relative_mean_error", number(m.relative_mean_error)}};
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
    heatmaps["abs_error"] = {{"png", "error_" + pair + ".png"}, {"colour_map", "viridis"}, {"min", number(abs_range.min)}, {"max", number(abs_range.max)}};
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
                    {"display_exposure", number(report_display_exposure(report))},
                    {"non_finite_numbers", "written as the strings \"inf\", \"-inf\", \"nan\""},
                    {"renders", renders},
                    {"comparisons", comparisons},
                    {"notes", report.notes}};
  return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";  // bad UTF-8 in a name → U+FFFD
}

}  // namespace volgraph::compare
