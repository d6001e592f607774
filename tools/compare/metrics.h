// How far a test image is from a reference image, in the figures `volgraph ab` and
// `volgraph sweep` report: RMSE, relative RMSE, PSNR, SSIM (Wang et al. 2004), HDR-FLIP
// (Andersson et al. 2020; flip.h), the largest absolute error and the non-finite
// values, over every pixel or over a mask. Both images are linear RGB (radiance).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tools/compare/rgb_image.h"

namespace volgraph::compare {

struct ErrorMetrics {
  size_t compared_pixels = 0;  // in the mask, both images finite there
  size_t nan_values = 0;       // NaN channel values of the test image inside the mask
  size_t inf_values = 0;       // ±Inf channel values of the test image inside the mask
  double rmse = 0;             // √(mean over channels of (test − ref)²)
  double relative_rmse = 0;    // rmse / √(mean over channels of ref²); 0 when both are 0
  double psnr_db = 0;          // 20 log10(peak / rmse), peak the reference's largest value; +inf when rmse is 0
  double ssim = 1;             // mean SSIM of the luminance (Wang et al. 2004), dynamic range = peak
  double flip = 0;             // mean HDR-FLIP (Andersson et al. 2020), 0 identical … 1
  double max_abs_error = 0;    // largest |test − ref| over channels
  double relative_mean_error = 0;  // Σ|test − ref| / Σ|ref| (the accuracy tests' metric)
};

// The figures over the pixels of `mask` (every pixel when it is empty). Pixels where
// the test image is not finite are counted (nan_values, inf_values) and left out of
// the other figures. Throws std::invalid_argument when the sizes differ.
ErrorMetrics measure_error(const RgbImage& test, const RgbImage& reference, const PixelMask& mask = {},
                           double pixels_per_degree = 67.0);

// Per-pixel maps for the heatmaps (row-major, one float a pixel): the largest absolute
// channel error, and the HDR-FLIP error (flip.h). Non-finite test pixels map to +inf.
std::vector<float> abs_error_map(const RgbImage& test, const RgbImage& reference);

// A metric by the name the command line and sweep specs use: "rmse", "rel_rmse",
// "psnr", "ssim", "flip", "max_abs", "rel_mean". Lower is better for every name except
// psnr and ssim: metric_value returns the figure as stored, metric_lower_is_better says
// which way is better.
const std::vector<std::string>& metric_names();
bool is_metric_name(const std::string& name);
double metric_value(const ErrorMetrics& metrics, const std::string& name);
bool metric_lower_is_better(const std::string& name);

}  // namespace volgraph::compare
