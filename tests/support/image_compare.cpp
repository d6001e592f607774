#include "tests/support/image_compare.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace volgraph::testing {

std::string ImageDifference::describe() const {
  std::ostringstream out;
  out << "relative mean error " << relative_mean_error << ", outliers " << outlier_fraction * 100 << " %, max abs error "
      << max_abs_error << ", non-finite values " << non_finite;
  return out.str();
}

ImageDifference compare_images(const std::vector<float>& a, const std::vector<float>& b, double outlier_threshold) {
  if (a.size() != b.size() || a.size() % 4) throw std::invalid_argument("compare_images: images differ in size");
  ImageDifference d;
  double error_sum = 0, reference_sum = 0;
  for (size_t i = 0; i < b.size(); ++i) {
    if (i % 4 != 3) reference_sum += std::abs(b[i]);
  }
  const size_t pixels = b.size() / 4;
  const double mean = pixels ? reference_sum / double(3 * pixels) : 0;
  size_t outliers = 0;
  for (size_t p = 0; p < pixels; ++p) {
    bool outlier = false;
    for (size_t c = 0; c < 3; ++c) {
      const double x = a[4 * p + c], y = b[4 * p + c];
      if (!std::isfinite(x)) {
        ++d.non_finite;
        outlier = true;
        continue;
      }
      const double e = std::abs(x - y);
      error_sum += e;
      d.max_abs_error = std::max(d.max_abs_error, e);
      outlier = outlier || e > outlier_threshold * std::max(std::abs(y), mean);
    }
    outliers += outlier ? 1 : 0;
  }
  d.relative_mean_error = reference_sum > 0 ? error_sum / reference_sum : error_sum;
  d.outlier_fraction = pixels ? double(outliers) / double(pixels) : 0;
  return d;
}

}  // namespace volgraph::testing
