#include <cctype>
#include <cstring>

#include "tools/compare/ab_report.h"
#include "tools/compare/display_image.h"
#include "tools/compare/heatmap.h"
#include "tools/image_io.h"

namespace volgraph::compare {
namespace {

using Files = std::vector<std::pair<std::string, std::vector<std::byte>>>;

std::vector<std::byte> owned_bytes(const std::string& text) {
  std::vector<std::byte> out(text.size());
  std::memcpy(out.data(), text.data(), text.size());
  return out;
}

std::vector<std::byte> png_of(const Rgba8Image& image) { return encode_png_rgba8(image.width, image.height, image.rgba); }

std::vector<std::byte> pfm_of(const RgbImage& image) {
  return encode_image(Image{image.width, image.height, rgba_from_rgb(image)}, ImageFormat::pfm);
}

std::pair<uint32_t, uint32_t> image_size(const AbReport& report) {
  if (report.renders.empty()) return {report.width, report.height};
  return {report.renders.front().image.width, report.renders.front().image.height};
}

void add_heatmaps(Files& files, const Comparison& comparison, const AbReport& report) {
  const auto [width, height] = image_size(report);
  const std::string pair = report_file_stem(comparison.test) + "_vs_" + report_file_stem(comparison.against);
  if (heatmap_fits(comparison.abs_error_map, report)) {
    const Rgba8Image map = heatmap_image(comparison.abs_error_map, width, height, ColourMap::viridis,
                                         abs_error_range(comparison.abs_error_map));
    files.emplace_back("error_" + pair + ".png", png_of(with_colour_bar(map, ColourMap::viridis, abs_error_range(comparison.abs_error_map))));
  }
  if (heatmap_fits(comparison.flip_map, report)) {
    const Rgba8Image map = heatmap_image(comparison.flip_map, width, height, ColourMap::magma, kFlipRange);
    files.emplace_back("flip_" + pair + ".png", png_of(with_colour_bar(map, ColourMap::magma, kFlipRange)));
  }
}

// The render called `label`, or null.
const Rendered* render_named(const AbReport& report, const std::string& label) {
  for (const Rendered& render : report.renders) {
    if (render.label == label) return &render;
  }
  return nullptr;
}

}  // namespace

bool heatmap_fits(const std::vector<float>& map, const AbReport& report) {
  const auto [width, height] = image_size(report);
  return !map.empty() && map.size() == size_t(width) * height;
}

std::string report_file_stem(const std::string& label) {
  std::string out;
  for (unsigned char ch : label) out += std::isalnum(ch) ? char(std::tolower(ch)) : '_';
  return out.empty() ? "_" : out;
}

double report_display_exposure(const AbReport& report) {
  if (report.renders.empty()) return 1.0;
  const Rendered* key = render_named(report, "reference");
  return display_exposure(key ? key->image : report.renders.front().image);
}

std::vector<std::pair<std::string, std::vector<std::byte>>> ab_report_files(const AbReport& report) {
  Files files;
  files.emplace_back("report.json", owned_bytes(ab_report_json(report)));
  files.emplace_back("report.html", owned_bytes(ab_report_html(report)));
  const double exposure = report_display_exposure(report);
  for (const Rendered& render : report.renders) {
    const std::string stem = report_file_stem(render.label);
    files.emplace_back(stem + ".png", png_of(display_image(render.image, exposure)));
    files.emplace_back(stem + ".pfm", pfm_of(render.image));
  }
  for (const Comparison& comparison : report.comparisons) add_heatmaps(files, comparison, report);
  return files;
}

}  // namespace volgraph::compare
