// Error maps as pictures: one value a pixel through a perceptually uniform colour map
// (matplotlib's viridis for absolute error; magma for FLIP, as the FLIP paper shows its
// error maps, Andersson et al. 2020), and the colour bar that reads a colour back as a value.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tools/compare/display_image.h"

namespace volgraph::compare {

enum class ColourMap { viridis, magma };

// The map's colour at t (sRGB-encoded, each channel in [0, 1]); t is clamped to [0, 1], NaN → 1.
std::array<double, 3> colour_at(ColourMap map, double t);

// Marks the pixels of a heatmap whose value is not finite (a NaN or Inf in the test image).
constexpr uint8_t kHeatmapNonFiniteColour[3] = {0, 255, 255};

// The range a heatmap spans: FLIP 0 … 1; absolute error 0 … the largest finite value.
struct HeatmapRange {
  double min = 0, max = 1;
};
HeatmapRange abs_error_range(const std::vector<float>& values);
constexpr HeatmapRange kFlipRange{0.0, 1.0};

// values (row-major, width × height) through the map over `range`.
Rgba8Image heatmap_image(const std::vector<float>& values, uint32_t width, uint32_t height, ColourMap map,
                         HeatmapRange range);

// A vertical colour bar: the map's top colour (range max) at the top row.
Rgba8Image colour_bar(ColourMap map, uint32_t width, uint32_t height);

// `heatmap` with a colour bar strip beside it on its right, a dark gap between, and the
// range's max and min written beside the bar's top and bottom (when the map is at least
// 20 pixels tall).
Rgba8Image with_colour_bar(const Rgba8Image& heatmap, ColourMap map, HeatmapRange range);

// A CSS linear-gradient (bottom to top) of the map, for the report page's colour bars.
std::string css_gradient(ColourMap map);

}  // namespace volgraph::compare
