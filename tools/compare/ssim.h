// SSIM (Wang, Bovik, Sheikh and Simoncelli 2004, "Image Quality Assessment: From Error
// Visibility to Structural Similarity", IEEE TIP 13(4)) of one channel: an 11x11
// Gaussian window of σ = 1.5 pixels, K₁ = 0.01, K₂ = 0.03. The window is clipped at the
// image's edges and its weights renormalised to sum to 1 over the pixels inside.
#pragma once

#include <cstdint>
#include <vector>

namespace volgraph::compare {

constexpr int kSsimWindowRadius = 5;  // 11x11
constexpr double kSsimSigma = 1.5;
constexpr double kSsimK1 = 0.01;
constexpr double kSsimK2 = 0.03;

// SSIM(x, y) at every pixel (row-major) of two planes of width x height values, with
// L = dynamic_range in C₁ = (K₁L)², C₂ = (K₂L)². Exactly 1 where the two agree over the window.
std::vector<double> ssim_map(const std::vector<double>& test, const std::vector<double>& reference, uint32_t width,
                             uint32_t height, double dynamic_range);

}  // namespace volgraph::compare
