#include "tools/compare/timing.h"

#include <algorithm>

namespace volgraph::compare {

// The median of an even count is the mean of the two middle samples.
Spread spread_of(std::vector<double> samples) {
  if (samples.empty()) return {};
  std::sort(samples.begin(), samples.end());
  const size_t n = samples.size();
  const double median = n % 2 ? samples[n / 2] : 0.5 * (samples[n / 2 - 1] + samples[n / 2]);
  return {median, samples.front(), samples.back(), int(n)};
}

}  // namespace volgraph::compare
