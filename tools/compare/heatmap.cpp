#include "tools/compare/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace volgraph::compare {
namespace {

using Coefficients = std::array<std::array<double, 3>, 7>;

// Degree-6 polynomial fits (Matt Zucker, shadertoy.com/view/WlfXRN, CC0) of matplotlib's
// viridis and magma (van der Walt and Smith, BIDS/colormap, CC0): c0 + t c1 + … + t⁶ c6.
constexpr Coefficients kViridis = {{{0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
                                    {0.1050930431085774, 1.404613529898575, 1.384590162594685},
                                    {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
                                    {-4.634230498983486, -5.799100973351585, -19.33244095627987},
                                    {6.228269936347081, 14.17993336680509, 56.69055260068105},
                                    {4.776384997670288, -13.74514537774601, -65.35303263337234},
                                    {-5.435455855934631, 4.645852612178535, 26.3124352495832}}};
constexpr Coefficients kMagma = {{{-0.002136485053939582, -0.000749655052795221, -0.005386127855323933},
                                  {0.2516605407371642, 0.6775232436837668, 2.494026599312351},
                                  {8.353717279216625, -3.577719514958484, 0.3144679030132573},
                                  {-27.66873308576866, 14.26473078096533, -13.64921318813922},
                                  {52.17613981234068, -27.94360607168351, 12.94416944238394},
                                  {-50.76852536473588, 29.04658282127291, 4.23415299384598},
                                  {18.65570506591883, -11.48977351997711, -5.601961508734096}}};

const Coefficients& coefficients(ColourMap map) { return map == ColourMap::viridis ? kViridis : kMagma; }

uint8_t to_byte(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

void put(uint8_t* texel, const std::array<double, 3>& colour) {
  for (int c = 0; c < 3; ++c) texel[c] = to_byte(colour[c]);
  texel[3] = 255;
}

constexpr uint8_t kGapColour = 32, kTextColour = 230;
constexpr uint32_t kGapWidth = 4;
constexpr uint32_t kLabelledHeight = 20;  // room for the two labels
constexpr int kTextHeight = 7;            // stb_easy_font's capitals and digits

std::string label_of(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

int text_width(std::string text) { return stb_easy_font_width(text.data()); }

// Text in stb_easy_font's segments (its quads are axis-aligned rectangles), top left at (x, y).
void draw_text(Rgba8Image& image, int x, int y, std::string text) {
  struct Vertex {
    float x, y, z;
    unsigned char colour[4];
  };
  std::vector<Vertex> quads(4 * 64 * text.size() + 4);
  unsigned char colour[4] = {kTextColour, kTextColour, kTextColour, 255};
  const int count = stb_easy_font_print(float(x), float(y), text.data(), colour, quads.data(), int(quads.size() * sizeof(Vertex)));
  for (int q = 0; q < count; ++q) {
    const Vertex* corner = &quads[4 * size_t(q)];
    const int x0 = std::max(0, int(std::lround(corner[0].x))), y0 = std::max(0, int(std::lround(corner[0].y)));
    const int x1 = std::min(int(image.width), int(std::lround(corner[2].x)));
    const int y1 = std::min(int(image.height), int(std::lround(corner[2].y)));
    for (int py = y0; py < y1; ++py) {
      for (int px = x0; px < x1; ++px) std::fill_n(&image.rgba[4 * (size_t(py) * image.width + px)], 3, kTextColour);
    }
  }
}

}  // namespace

std::array<double, 3> colour_at(ColourMap map, double t) {
  const Coefficients& k = coefficients(map);
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 1.0;
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c) {
    double v = k[6][c];
    for (int i = 5; i >= 0; --i) v = v * t + k[size_t(i)][c];  // Horner
    out[size_t(c)] = std::clamp(v, 0.0, 1.0);
  }
  return out;
}

HeatmapRange abs_error_range(const std::vector<float>& values) {
  double largest = 0;
  for (float v : values) {
    if (std::isfinite(v)) largest = std::max(largest, double(v));
  }
  return {0.0, largest};
}

Rgba8Image heatmap_image(const std::vector<float>& values, uint32_t width, uint32_t height, ColourMap map,
                         HeatmapRange range) {
  Rgba8Image out{width, height, std::vector<uint8_t>(size_t(width) * height * 4, 255)};
  const double span = range.max - range.min;
  for (size_t p = 0; p < out.rgba.size() / 4 && p < values.size(); ++p) {
    uint8_t* texel = &out.rgba[4 * p];
    if (!std::isfinite(values[p])) {
      std::copy(kHeatmapNonFiniteColour, kHeatmapNonFiniteColour + 3, texel);
      continue;
    }
    const double t = span > 0 ? (values[p] - range.min) / span : 0.0;
    put(texel, colour_at(map, t));
  }
  return out;
}

Rgba8Image colour_bar(ColourMap map, uint32_t width, uint32_t height) {
  Rgba8Image out{width, height, std::vector<uint8_t>(size_t(width) * height * 4, 255)};
  for (uint32_t y = 0; y < height; ++y) {
    const double t = height > 1 ? 1.0 - double(y) / double(height - 1) : 1.0;
    const auto colour = colour_at(map, t);
    for (uint32_t x = 0; x < width; ++x) put(&out.rgba[4 * (size_t(y) * width + x)], colour);
  }
  return out;
}

Rgba8Image with_colour_bar(const Rgba8Image& heatmap, ColourMap map, HeatmapRange range) {
  const uint32_t bar_width = std::max<uint32_t>(6, heatmap.width / 16);
  const Rgba8Image bar = colour_bar(map, bar_width, heatmap.height);
  const std::string top = label_of(range.max), bottom = label_of(range.min);
  const bool labelled = heatmap.height >= kLabelledHeight;
  const uint32_t label_width = labelled ? kGapWidth + uint32_t(std::max(text_width(top), text_width(bottom))) + 1 : 0;
  const uint32_t width = heatmap.width + kGapWidth + bar_width + label_width;
  Rgba8Image out{width, heatmap.height, std::vector<uint8_t>(size_t(width) * heatmap.height * 4, kGapColour)};
  for (uint32_t y = 0; y < heatmap.height; ++y) {
    uint8_t* row = &out.rgba[4 * size_t(y) * width];
    for (uint32_t x = 0; x < width; ++x) row[4 * x + 3] = 255;
    std::copy_n(&heatmap.rgba[4 * size_t(y) * heatmap.width], 4 * heatmap.width, row);
    std::copy_n(&bar.rgba[4 * size_t(y) * bar_width], 4 * bar_width, row + 4 * (heatmap.width + kGapWidth));
  }
  if (!labelled) return out;
  const int text_x = int(heatmap.width + 2 * kGapWidth + bar_width);
  draw_text(out, text_x, 1, top);
  draw_text(out, text_x, int(heatmap.height) - kTextHeight - 1, bottom);
  return out;
}

std::string css_gradient(ColourMap map) {
  constexpr int kStops = 17;
  std::string out = "linear-gradient(to top";
  for (int i = 0; i < kStops; ++i) {
    const double t = double(i) / (kStops - 1);
    const auto colour = colour_at(map, t);
    char stop[48];
    std::snprintf(stop, sizeof stop, ", rgb(%d,%d,%d) %.2f%%", to_byte(colour[0]), to_byte(colour[1]), to_byte(colour[2]),
                  100.0 * t);
    out += stop;
  }
  return out + ")";
}

}  // namespace volgraph::compare
