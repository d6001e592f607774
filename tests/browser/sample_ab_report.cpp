// Writes the report files of an A/B report built from synthetic images of known, very
// different content into a directory, for check_report.sh: A a red ramp left to right,
// B a blue one, the reference a green ramp top to bottom, 64x36. Usage: sample_ab_report DIR
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "tools/compare/ab_report.h"

namespace volgraph::compare {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 36;

// `channel` ramps from 0.015 at the left to 0.105 at the right (shown from dark to
// bright at the exposure the green reference sets); the other channels are 0.
RgbImage ramp(int channel) {
  RgbImage image{kWidth, kHeight, std::vector<float>(size_t(kWidth) * kHeight * 3, 0.0f)};
  for (uint32_t y = 0; y < kHeight; ++y) {
    for (uint32_t x = 0; x < kWidth; ++x) image.rgb[3 * (size_t(y) * kWidth + x) + size_t(channel)] = 0.015f + 0.09f * x / (kWidth - 1);
  }
  return image;
}

// The figures this sample can state exactly without the metrics library: the largest
// absolute error and RMSE against the reference. SSIM and FLIP are left at their
// defaults, and the FLIP map is a ramp, as the notes say: the page is under test here.
Comparison compare(const Rendered& test, const Rendered& reference) {
  Comparison comparison{test.label, reference.label, {}, {}, {}};
  double squares = 0, largest = 0;
  for (size_t p = 0; p < test.image.pixels(); ++p) {
    float worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const float d = test.image.rgb[3 * p + c] - reference.image.rgb[3 * p + c];
      squares += double(d) * d;
      worst = std::max(worst, std::abs(d));
    }
    comparison.abs_error_map.push_back(worst);
    comparison.flip_map.push_back(float(p % kWidth) / (kWidth - 1));
    largest = std::max(largest, double(worst));
  }
  ErrorMetrics metrics;
  metrics.compared_pixels = test.image.pixels();
  metrics.rmse = std::sqrt(squares / double(test.image.rgb.size()));
  metrics.max_abs_error = largest;
  comparison.by_mask.push_back({"all pixels", test.image.pixels(), metrics});
  return comparison;
}

TimingSummary synthetic_timing(double frame_ms) {
  TimingSummary timing{5, 2, {frame_ms, frame_ms * 0.9, frame_ms * 1.2, 5}, {}, true, "synthetic times of the sample report"};
  timing.passes.push_back({"fog_media", "froxel_voxelize", {1.5, 1.25, 2.0, 5}, {0.1, 0.08, 0.2, 5}});
  timing.passes.push_back({"fog_integral", "scatter_integrate", {frame_ms / 2, frame_ms / 3, frame_ms, 5}, {0.1, 0.05, 0.3, 5}});
  return timing;
}

AbReport sample_report() {
  AbReport report;
  report.volgraph_version = "sample";
  report.command_line = "sample_ab_report DIR";
  report.config = "sample <synthetic> & \"quoted\".json";
  report.pass = "fog_integral";
  report.backend = "vulkan";
  report.device = "llvmpipe (sample)";
  report.driver = "none";
  report.device_is_cpu = true;
  report.width = kWidth;
  report.height = kHeight;
  RgbImage green{kWidth, kHeight, {}};
  for (size_t p = 0; p < green.pixels(); ++p) green.rgb.insert(green.rgb.end(), {0.0f, 0.05f + 0.1f * float(p / kWidth) / (kHeight - 1), 0.0f});
  report.renders.push_back({"A", "red ramp, dark to bright left to right", "sample A", ramp(0), synthetic_timing(8.0), MemorySummary{1 << 20, 3 << 20, 1 << 19, 4096, 5, 1}, 0});
  report.renders.push_back({"B", "blue ramp, dark to bright left to right", "sample B", ramp(2), synthetic_timing(6.0), MemorySummary{1 << 21, 1 << 22, 1 << 20, 4096, 4, 2}, 0});
  report.renders.push_back({"reference", "green ramp, dark to bright top to bottom", "sample reference", green, std::nullopt, std::nullopt, 1.5});
  report.comparisons.push_back(compare(report.renders[0], report.renders[2]));
  report.comparisons.push_back(compare(report.renders[1], report.renders[2]));
  report.notes = {"a synthetic report for the browser test: the times are made up, SSIM and FLIP are not measured and the "
                  "FLIP map is a ramp"};
  return report;
}

}  // namespace
}  // namespace volgraph::compare

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: sample_ab_report DIR\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  for (const auto& [name, bytes] : volgraph::compare::ab_report_files(volgraph::compare::sample_report())) {
    std::ofstream out(dir / name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out.flush()) {
      std::fprintf(stderr, "sample_ab_report: cannot write %s\n", (dir / name).c_str());
      return 1;
    }
  }
  return 0;
}
