// FLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild 2020,
// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020) and its HDR variant
// (Andersson, Nilsson, Shirley and Akenine-Möller 2021, "Visualizing Errors in Rendered
// High Dynamic Range Images", Eurographics short paper): a per-pixel perceptual error in
// [0, 1] between a test and a reference image seen at `pixels_per_degree`. Written from
// the papers; the separable form of the filters is the one NVlabs' FLIP uses (its
// misc/separatedConvolutions.pdf), borders clamp to the edge pixel.
//
// A pixel where the test or the reference has a NaN or ±Inf channel gets +inf in the
// maps; for the filters around it the test takes the reference's value there (0 for
// both when the reference is not finite either), so its neighbours see no error from it.
// Throws std::invalid_argument when the sizes differ or pixels_per_degree is not > 0.
#pragma once

#include <vector>

#include "tools/compare/rgb_image.h"

namespace volgraph::compare {

// FLIP's default observer: 0.7 m from a 0.7 m wide 3840-pixel monitor.
constexpr double kFlipPixelsPerDegree = 67.0;

// LDR-FLIP of two sRGB-encoded images with values in [0, 1] (clamped): one error a pixel.
// Symmetric: swapping test and reference gives the same map.
std::vector<float> flip_ldr_map(const RgbImage& test_srgb, const RgbImage& reference_srgb,
                                double pixels_per_degree = kFlipPixelsPerDegree);

// The exposures HDR-FLIP evaluates (Andersson et al. 2021): start = log2(x₀.₈₅ / Y_max),
// stop = log2(x₀.₈₅ / Y_median), with x₀.₈₅ the value the tone mapper maps to 0.85 and Y
// the Rec. 709 luminance of the image's finite pixels (the median is the element at n/2
// of the sorted luminances); `count` = max(2, ⌈stop − start⌉), evenly spaced.
// Where the paper's rule has no answer: when the median is ≤ 0 (half the pixels black or
// below) the median of the positive luminances is used; `found` is false when no
// luminance is positive (then start = stop = 0).
struct FlipExposures {
  double start = 0;
  double stop = 0;
  int count = 2;
  bool found = false;
};
FlipExposures flip_hdr_exposures(const RgbImage& linear);

// The ACES filmic curve as FLIP uses it (Narkowicz's fit, with FLIP's 0.6 pre-exposure
// folded into the coefficients), one channel, not clamped.
double flip_aces_tonemap(double x);

// HDR-FLIP of two linear images: LDR-FLIP after the ACES tone mapper (clamped to [0, 1])
// at each exposure between the start and stop exposures found from the reference (from
// the test when the reference has no positive luminance; exposure 0 when neither has),
// the largest per pixel. Invariant to scaling both images by one positive factor.
std::vector<float> flip_hdr_map(const RgbImage& test, const RgbImage& reference,
                                double pixels_per_degree = kFlipPixelsPerDegree);

}  // namespace volgraph::compare
