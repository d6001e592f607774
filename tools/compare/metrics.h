// How far a test image is from a reference image, in the figures `volgraph ab` and
// `volgraph sweep` report: RMSE, relative RMSE, PSNR, SSIM (Wang et al. 2004), HDR-FLIP
// (Andersson et al. 2021; flip.h), the largest absolute error and the non-finite
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
  double psnr_db = 0;          // 20 log10(peak / rmse), peak the reference's largest value (1 if ≤ 0); +inf when rmse is 0
  double ssim = 1;             // mean SSIM of the Rec. 709 luminance (Wang et al. 2004), dynamic range = peak
  double flip = 0;             // mean HDR-FLIP (Andersson et al. 2021, flip.h), 0 identical … 1
  double max_abs_error = 0;    // largest |test − ref| over channels
  double relative_mean_error = 0;  // Σ|test − ref| / Σ|ref| (the accuracy tests' metric)
};

// The figures over the pixels of `mask` (every pixel when it is empty). Pixels where
// the test image is not finite are counted (nan_values, inf_values) and left out of
// the other figures (so are pixels where the reference is not finite, uncounted). When no
// pixel is compared every figure is NaN: no comparison is never a perfect score.
// Throws std::invalid_argument when the image sizes differ or the mask is neither empty
// nor one value a pixel.
//
// Where a figure has no answer from its formula:
// - peak: the reference's largest channel value over the compared pixels; when that is
//   not > 0 (a black reference) the dynamic range is taken as 1 for PSNR and SSIM;
// - relative_rmse and relative_mean_error are +inf when the reference is 0 over the
//   compared pixels and the test is not (0 when both are);
// - with no compared pixels every figure keeps its no-error value (rmse 0, psnr +inf,
//   ssim 1, flip 0 …): compared_pixels, nan_values and inf_values tell why.
// Pixels left out (a NaN or ±Inf channel in the test or the reference): SSIM's and FLIP's
// windows see the reference's value in the test there (0 in both where the reference is
// not finite), and their means leave those pixels out. SSIM's and FLIP's windows reach
// pixels outside the mask; their means are over the mask's compared pixels (the window
// centred on each). SSIM is of the Rec. 709 luminance (ssim.h), FLIP is HDR-FLIP (flip.h)
// of the whole image at `pixels_per_degree`.
ErrorMetrics measure_error(const RgbImage& test, const RgbImage& reference, const PixelMask& mask = {},
                           double pixels_per_degree = 67.0);

// The same with the HDR-FLIP map already computed (flip_hdr_map(test, reference, ppd)),
// so that several masks of one pair of images share it. Throws std::invalid_argument
// when its size is not one value a pixel.
ErrorMetrics measure_error_with_flip_map(const RgbImage& test, const RgbImage& reference, const PixelMask& mask,
                                         const std::vector<float>& flip_map);

// Per-pixel maps for the heatmaps (row-major, one float a pixel): the largest absolute
// channel error here, the HDR-FLIP error in flip.h (flip_hdr_map). Pixels where the test
// (or the reference) is not finite map to +inf. Throws std::invalid_argument when the
// sizes differ.
std::vector<float> abs_error_map(const RgbImage& test, const RgbImage& reference);

// A metric by the name the command line and sweep specs use: "rmse", "rel_rmse",
// "psnr", "ssim", "flip", "max_abs", "rel_mean". Lower is better for every name except
// psnr and ssim: metric_value returns the figure as stored, metric_lower_is_better says
// which way is better. Both throw std::invalid_argument for any other name.
const std::vector<std::string>& metric_names();
bool is_metric_name(const std::string& name);
double metric_value(const ErrorMetrics& metrics, const std::string& name);
bool metric_lower_is_better(const std::string& name);

}  // namespace volgraph::compare
