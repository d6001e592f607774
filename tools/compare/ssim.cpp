// SSIM (ssim.h): local means, variances and covariance through a separable Gaussian
// window, combined as Wang et al. 2004, eq. 13.
#include "tools/compare/ssim.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace volgraph::compare {
namespace {

std::vector<double> window_weights() {
  std::vector<double> w(2 * kSsimWindowRadius + 1);
  for (int i = -kSsimWindowRadius; i <= kSsimWindowRadius; ++i) {
    w[i + kSsimWindowRadius] = std::exp(-double(i * i) / (2.0 * kSsimSigma * kSsimSigma));
  }
  return w;
}

// The weighted mean of `values` along one axis: `count` lines of `length` samples, the
// sample i of line l at values[l * line_stride + i * sample_stride]; the window is cut
// at the ends and renormalised. The 2-D window is the product of two 1-D ones, so cutting
// and renormalising each axis cuts and renormalises the 2-D window.
std::vector<double> windowed_mean(const std::vector<double>& values, size_t count, size_t length, size_t line_stride,
                                  size_t sample_stride, const std::vector<double>& w) {
  std::vector<double> out(values.size());
  const int r = kSsimWindowRadius, n = int(length);
  for (size_t l = 0; l < count; ++l) {
    for (int i = 0; i < n; ++i) {
      double sum = 0, weight = 0;
      for (int j = std::max(-r, -i); j <= std::min(r, n - 1 - i); ++j) {
        sum += w[j + r] * values[l * line_stride + size_t(i + j) * sample_stride];
        weight += w[j + r];
      }
      out[l * line_stride + size_t(i) * sample_stride] = sum / weight;
    }
  }
  return out;
}

std::vector<double> window_mean(const std::vector<double>& values, uint32_t width, uint32_t height,
                                const std::vector<double>& w) {
  const std::vector<double> rows = windowed_mean(values, height, width, width, 1, w);
  return windowed_mean(rows, width, height, 1, width, w);
}

std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(a.size());
  for (size_t i = 0; i < a.size(); ++i) out[i] = a[i] * b[i];
  return out;
}

}  // namespace

std::vector<double> ssim_map(const std::vector<double>& test, const std::vector<double>& reference, uint32_t width,
                             uint32_t height, double dynamic_range) {
  const std::vector<double> w = window_weights();
  const std::vector<double> mean_x = window_mean(test, width, height, w);
  const std::vector<double> mean_y = window_mean(reference, width, height, w);
  const std::vector<double> mean_xx = window_mean(product(test, test), width, height, w);
  const std::vector<double> mean_yy = window_mean(product(reference, reference), width, height, w);
  const std::vector<double> mean_xy = window_mean(product(test, reference), width, height, w);
  const double c1 = (kSsimK1 * dynamic_range) * (kSsimK1 * dynamic_range);
  const double c2 = (kSsimK2 * dynamic_range) * (kSsimK2 * dynamic_range);
  std::vector<double> out(test.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const double mx = mean_x[i], my = mean_y[i];
    const double var_x = mean_xx[i] - mx * mx, var_y = mean_yy[i] - my * my, cov = mean_xy[i] - mx * my;
    // SSIM = (2μxμy + C₁)(2σxy + C₂) / ((μx² + μy² + C₁)(σx² + σy² + C₂)), Wang et al. 2004 eq. 13
    out[i] = ((2 * mx * my + c1) * (2 * cov + c2)) / ((mx * mx + my * my + c1) * (var_x + var_y + c2));
  }
  return out;
}

}  // namespace volgraph::compare
