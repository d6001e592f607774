// The metrics by the names the command line and sweep specs use (metrics.h).
#include <algorithm>
#include <stdexcept>

#include "tools/compare/metrics.h"

namespace volgraph::compare {

const std::vector<std::string>& metric_names() {
  static const std::vector<std::string> names{"rmse", "rel_rmse", "psnr", "ssim", "flip", "max_abs", "rel_mean"};
  return names;
}

bool is_metric_name(const std::string& name) {
  const std::vector<std::string>& names = metric_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

double metric_value(const ErrorMetrics& metrics, const std::string& name) {
  if (name == "rmse") return metrics.rmse;
  if (name == "rel_rmse") return metrics.relative_rmse;
  if (name == "psnr") return metrics.psnr_db;
  if (name == "ssim") return metrics.ssim;
  if (name == "flip") return metrics.flip;
  if (name == "max_abs") return metrics.max_abs_error;
  if (name == "rel_mean") return metrics.relative_mean_error;
  throw std::invalid_argument("no metric named \"" + name + "\"");
}

bool metric_lower_is_better(const std::string& name) {
  if (!is_metric_name(name)) throw std::invalid_argument("no metric named \"" + name + "\"");
  return name != "psnr" && name != "ssim";
}

}  // namespace volgraph::compare
