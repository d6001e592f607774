// FLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild 2020,
// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020) and its HDR variant
// (Andersson et al. 2021, "Visualizing Errors in Rendered High Dynamic Range Images",
// Eurographics short paper): a per-pixel perceptual error in [0, 1] between a test and
// a reference image seen at `pixels_per_degree`. Written from the papers.
#pragma once

#include <vector>

#include "tools/compare/rgb_image.h"

namespace volgraph::compare {

// FLIP's default observer: 0.7 m from a 0.7 m wide 3840-pixel monitor.
constexpr double kFlipPixelsPerDegree = 67.0;

// LDR-FLIP of two sRGB-encoded images with values in [0, 1] (clamped): one error a pixel.
std::vector<float> flip_ldr_map(const RgbImage& test_srgb, const RgbImage& reference_srgb,
                                double pixels_per_degree = kFlipPixelsPerDegree);

// HDR-FLIP of two linear images: LDR-FLIP after the ACES tone mapper at each exposure
// between the start and stop exposures found from the reference, the largest per pixel.
std::vector<float> flip_hdr_map(const RgbImage& test, const RgbImage& reference,
                                double pixels_per_degree = kFlipPixelsPerDegree);

}  // namespace volgraph::compare
