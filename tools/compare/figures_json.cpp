#include "tools/compare/figures_json.h"

#include <cmath>

namespace volgraph::compare {

Json number_json(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

Json spread_json(const Spread& s) {
  return {{"median", number_json(s.median)}, {"min", number_json(s.min)}, {"max", number_json(s.max)}, {"runs", s.runs}};
}

Json timing_json(const TimingSummary& t) {
  Json passes = Json::array();
  for (const PassTimes& p : t.passes) {
    passes.push_back({{"pass", p.pass}, {"type", p.type}, {"gpu_ms", spread_json(p.gpu_ms)}, {"cpu_ms", spread_json(p.cpu_ms)}});
  }
  return {{"runs", t.runs},
          {"warmup", t.warmup},
          {"frame_wall_ms", spread_json(t.frame_wall_ms)},
          {"passes", passes},
          {"gpu_timestamps", t.gpu_timestamps},
          {"clock", t.clock}};
}

Json memory_json(const MemorySummary& m) {
  return {{"aliased_bytes", m.aliased_bytes},         {"unaliased_bytes", m.unaliased_bytes},
          {"lower_bound_bytes", m.lower_bound_bytes}, {"persistent_bytes", m.persistent_bytes},
          {"passes_run", m.passes_run},               {"passes_culled", m.passes_culled}};
}

Json metrics_json(const ErrorMetrics& m) {
  return {{"compared_pixels", m.compared_pixels},
          {"nan_values", m.nan_values},
          {"inf_values", m.inf_values},
          {"rmse", number_json(m.rmse)},
          {"relative_rmse", number_json(m.relative_rmse)},
          {"psnr_db", number_json(m.psnr_db)},
          {"ssim", number_json(m.ssim)},
          {"flip", number_json(m.flip)},
          {"max_abs_error", number_json(m.max_abs_error)},
          {"relative_mean_error", number_json(m.relative_mean_error)}};
}

}  // namespace volgraph::compare
