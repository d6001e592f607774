// The A/B report files: report.json holds every figure (exact values read back),
// report.html needs nothing outside itself and escapes what it shows, the images and
// heatmaps are the PNGs they claim to be, and the display helpers map known values to
// known colours.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tools/compare/ab_report.h"
#include "tools/compare/display_image.h"
#include "tools/compare/heatmap.h"

namespace volgraph::compare {
namespace {

using Json = nlohmann::json;

RgbImage flat_image(uint32_t width, uint32_t height, float r, float g, float b) {
  RgbImage image{width, height, {}};
  for (size_t p = 0; p < image.pixels(); ++p) image.rgb.insert(image.rgb.end(), {r, g, b});
  return image;
}

TimingSummary timing(double frame_median) {
  TimingSummary t;
  t.runs = 5;
  t.warmup = 2;
  t.gpu_timestamps = true;
  t.clock = "lavapipe (CPU): times are CPU times";
  t.frame_wall_ms = {frame_median, frame_median - 0.5, frame_median + 1.25, 5};
  t.passes.push_back({"fog_integral", "scatter_integrate", {0.75, 0.5, 1.0, 5}, {0.125, 0.1, 0.2, 5}});
  return t;
}

// A vs reference with a known error, B identical to the reference (PSNR +inf).
AbReport sample_report() {
  AbReport report;
  report.volgraph_version = "v1.2-3-gabcdef";
  report.command_line = "volgraph ab configs/demo_fog.json --a fog_integral=wronski --b fog_integral=hillaire";
  report.config = "configs/demo_fog.json";
  report.pass = "fog_integral";
  report.backend = "vulkan";
  report.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
  report.driver = "Mesa 22.3.6";
  report.device_is_cpu = true;
  report.width = 4;
  report.height = 2;
  report.frames = 3;
  Rendered a{"A", "scatter_integrate=wronski", "volgraph render configs/demo_fog.json -o a.png", flat_image(4, 2, 0.5f, 0, 0),
             timing(12.5), MemorySummary{1048576, 2097152, 524288, 4096, 7, 2}, 0};
  Rendered b{"B", "scatter_integrate=hillaire", "volgraph render configs/demo_fog.json -o b.png", flat_image(4, 2, 0, 0, 0.5f),
             timing(10.0), MemorySummary{3, 4, 2, 1, 6, 1}, 0};
  Rendered reference{"reference", "CPU reference", "volgraph reference configs/demo_fog.json -o r.pfm",
                     flat_image(4, 2, 0, 0.5f, 0), std::nullopt, std::nullopt, 4.5};
  report.renders = {a, b, reference};
  Comparison a_ref{"A", "reference", {}, std::vector<float>(8, 0.5f), std::vector<float>(8, 0.25f)};
  ErrorMetrics m;
  m.compared_pixels = 8;
  m.rmse = 0.40824829046386296;
  m.relative_rmse = 1.4142135623730951;
  m.psnr_db = 1.760912590556812;
  m.ssim = 0.0123;
  m.flip = 0.25;
  m.max_abs_error = 0.5;
  m.relative_mean_error = 2.0;
  a_ref.by_mask.push_back({"all pixels", 8, m});
  m.compared_pixels = 3;
  m.nan_values = 1;
  a_ref.by_mask.push_back({"fog-only pixels", 4, m});
  Comparison b_ref{"B", "reference", {}, std::vector<float>(8, 0.0f), std::vector<float>(8, 0.0f)};
  ErrorMetrics exact;
  exact.compared_pixels = 8;
  exact.psnr_db = std::numeric_limits<double>::infinity();
  b_ref.by_mask.push_back({"all pixels", 8, exact});
  report.comparisons = {a_ref, b_ref};
  report.notes = {"times: lavapipe (CPU)", "the reference has no froxel grid"};
  return report;
}

TEST(AbReportJson, ParsesAndHoldsEveryFigure) {
  const Json json = Json::parse(ab_report_json(sample_report()));
  EXPECT_EQ(json["volgraph_version"], "v1.2-3-gabcdef");
  EXPECT_EQ(json["command_line"], sample_report().command_line);
  EXPECT_EQ(json["config"], "configs/demo_fog.json");
  EXPECT_EQ(json["pass"], "fog_integral");
  EXPECT_EQ(json["backend"], "vulkan");
  EXPECT_EQ(json["device"], "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_EQ(json["driver"], "Mesa 22.3.6");
  EXPECT_EQ(json["device_is_cpu"], true);
  EXPECT_EQ(json["width"], 4);
  EXPECT_EQ(json["height"], 2);
  EXPECT_EQ(json["frames"], 3);
  EXPECT_DOUBLE_EQ(json["display_exposure"].get<double>(), kDisplayKeyValue / (0.7152 * 0.5)) << "from the reference";
  ASSERT_EQ(json["renders"].size(), 3u);
  const Json& a = json["renders"][0];
  EXPECT_EQ(a["label"], "A");
  EXPECT_EQ(a["setting"], "scatter_integrate=wronski");
  EXPECT_EQ(a["command"], "volgraph render configs/demo_fog.json -o a.png");
  EXPECT_EQ(a["png"], "a.png");
  EXPECT_EQ(a["pfm"], "a.pfm");
  EXPECT_EQ(a["timing"]["runs"], 5);
  EXPECT_EQ(a["timing"]["warmup"], 2);
  EXPECT_EQ(a["timing"]["gpu_timestamps"], true);
  EXPECT_EQ(a["timing"]["clock"], "lavapipe (CPU): times are CPU times");
  EXPECT_EQ(a["timing"]["frame_wall_ms"]["median"], 12.5);
  EXPECT_EQ(a["timing"]["frame_wall_ms"]["min"], 12.0);
  EXPECT_EQ(a["timing"]["frame_wall_ms"]["max"], 13.75);
  EXPECT_EQ(a["timing"]["frame_wall_ms"]["runs"], 5);
  const Json& pass = a["timing"]["passes"][0];
  EXPECT_EQ(pass["pass"], "fog_integral");
  EXPECT_EQ(pass["type"], "scatter_integrate");
  EXPECT_EQ(pass["gpu_ms"]["median"], 0.75);
  EXPECT_EQ(pass["cpu_ms"]["max"], 0.2);
  EXPECT_EQ(a["memory"]["aliased_bytes"], 1048576);
  EXPECT_EQ(a["memory"]["unaliased_bytes"], 2097152);
  EXPECT_EQ(a["memory"]["lower_bound_bytes"], 524288);
  EXPECT_EQ(a["memory"]["persistent_bytes"], 4096);
  EXPECT_EQ(a["memory"]["passes_run"], 7);
  EXPECT_EQ(a["memory"]["passes_culled"], 2);
  const Json& reference = json["renders"][2];
  EXPECT_TRUE(reference["timing"].is_null());
  EXPECT_TRUE(reference["memory"].is_null());
  EXPECT_EQ(reference["seconds"], 4.5);
  ASSERT_EQ(json["comparisons"].size(), 2u);
  const Json& a_ref = json["comparisons"][0];
  EXPECT_EQ(a_ref["test"], "A");
  EXPECT_EQ(a_ref["against"], "reference");
  ASSERT_EQ(a_ref["by_mask"].size(), 2u);
  const Json& all = a_ref["by_mask"][0];
  EXPECT_EQ(all["mask"], "all pixels");
  EXPECT_EQ(all["mask_pixels"], 8);
  EXPECT_EQ(all["metrics"]["rmse"].get<double>(), 0.40824829046386296);  // written with every digit
  EXPECT_EQ(all["metrics"]["relative_rmse"].get<double>(), 1.4142135623730951);
  EXPECT_EQ(all["metrics"]["psnr_db"].get<double>(), 1.760912590556812);
  EXPECT_EQ(all["metrics"]["ssim"], 0.0123);
  EXPECT_EQ(all["metrics"]["flip"], 0.25);
  EXPECT_EQ(all["metrics"]["max_abs_error"], 0.5);
  EXPECT_EQ(all["metrics"]["relative_mean_error"], 2.0);
  EXPECT_EQ(a_ref["by_mask"][1]["mask"], "fog-only pixels");
  EXPECT_EQ(a_ref["by_mask"][1]["metrics"]["compared_pixels"], 3);
  EXPECT_EQ(a_ref["by_mask"][1]["metrics"]["nan_values"], 1);
  EXPECT_EQ(a_ref["by_mask"][1]["metrics"]["inf_values"], 0);
  EXPECT_EQ(a_ref["heatmaps"]["abs_error"]["png"], "error_a_vs_reference.png");
  EXPECT_EQ(a_ref["heatmaps"]["abs_error"]["max"], 0.5);
  EXPECT_EQ(a_ref["heatmaps"]["flip"]["png"], "flip_a_vs_reference.png");
  EXPECT_EQ(json["notes"], Json({"times: lavapipe (CPU)", "the reference has no froxel grid"}));
}

TEST(AbReportJson, InfinitePsnrIsAStringAndTheFileStaysValid) {
  AbReport report = sample_report();
  report.comparisons[0].by_mask[0].metrics.ssim = std::numeric_limits<double>::quiet_NaN();
  report.comparisons[0].by_mask[0].metrics.rmse = -std::numeric_limits<double>::infinity();
  const std::string text = ab_report_json(report);
  ASSERT_TRUE(Json::accept(text));
  const Json json = Json::parse(text);
  EXPECT_EQ(json["comparisons"][1]["by_mask"][0]["metrics"]["psnr_db"], "inf");
  EXPECT_EQ(json["comparisons"][0]["by_mask"][0]["metrics"]["ssim"], "nan");
  EXPECT_EQ(json["comparisons"][0]["by_mask"][0]["metrics"]["rmse"], "-inf");
}

TEST(AbReportHtml, FetchesNothingAndEmbedsEveryImage) {
  const std::string html = ab_report_html(sample_report());
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_FALSE(std::regex_search(html, std::regex(R"((src|href)\s*=\s*["']?//)")));
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(\s(src|href)\s*=\s*["']?(?!data:image/png;base64,)[^"'\s>])")))
      << "every src and href is a PNG data: URI";
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("url("), std::string::npos);
  EXPECT_NE(html.find("default-src 'none'"), std::string::npos);
  for (const std::string layer : {"a", "b", "reference", "error-a-vs-reference", "flip-a-vs-reference",
                                  "error-b-vs-reference", "flip-b-vs-reference"}) {
    EXPECT_TRUE(std::regex_search(html, std::regex("data-layer=\"" + layer + "\"[^>]*src=\"data:image/png;base64,[A-Za-z0-9+/]+=*\"")))
        << layer;
    EXPECT_NE(html.find("id=\"show-" + layer + "\""), std::string::npos) << layer;
  }
}

TEST(AbReportHtml, ShowsTheCpuNoteAndTheTables) {
  const std::string html = ab_report_html(sample_report());
  EXPECT_NE(html.find("lavapipe (CPU): the GPU is this CPU; times are CPU times"), std::string::npos);
  EXPECT_NE(html.find("id=\"metrics-table\""), std::string::npos);
  EXPECT_NE(html.find("fog-only pixels"), std::string::npos);
  EXPECT_NE(html.find("<td>∞</td>"), std::string::npos) << "B's PSNR";
  EXPECT_NE(html.find("12.500 <small>[12.000–13.750]</small>"), std::string::npos) << "A's frame time";
  EXPECT_NE(html.find("1.00 MiB"), std::string::npos) << "A's aliased memory";
  EXPECT_NE(html.find("4.00 KiB"), std::string::npos) << "A's persistent memory";
  EXPECT_NE(html.find(">3 B<"), std::string::npos) << "B's aliased memory";
  EXPECT_NE(html.find("report ready"), std::string::npos);

  AbReport gpu = sample_report();
  gpu.device_is_cpu = false;
  EXPECT_EQ(ab_report_html(gpu).find("the GPU is this CPU"), std::string::npos);
}

TEST(AbReportHtml, EscapesNamesSettingsAndCommands) {
  AbReport report = sample_report();
  report.config = "<script>alert(1)</script>.json";
  report.renders[0].setting = "a=\"<b>\" & 'c'";
  report.renders[1].command = "volgraph render </code><script>x()</script>";
  report.comparisons[0].by_mask[1].mask = "<img src=x>";
  report.notes.push_back("</li><script>y()</script>");
  const std::string html = ab_report_html(report);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_EQ(html.find("<script>x()"), std::string::npos);
  EXPECT_EQ(html.find("<script>y()"), std::string::npos);
  EXPECT_EQ(html.find("<img src=x>"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert(1)&lt;/script&gt;.json"), std::string::npos);
  EXPECT_NE(html.find("a=&quot;&lt;b&gt;&quot; &amp; &#39;c&#39;"), std::string::npos);
  size_t scripts = 0;
  for (size_t at = html.find("<script"); at != std::string::npos; at = html.find("<script", at + 1)) ++scripts;
  EXPECT_EQ(scripts, 1u) << "only the page's own script";
}

TEST(AbReportFiles, NamesEveryFileInOrder) {
  const auto files = ab_report_files(sample_report());
  std::vector<std::string> names;
  for (const auto& [name, bytes] : files) {
    names.push_back(name);
    EXPECT_FALSE(bytes.empty()) << name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"report.json", "report.html", "a.png", "a.pfm", "b.png", "b.pfm", "reference.png",
                                             "reference.pfm", "error_a_vs_reference.png", "flip_a_vs_reference.png",
                                             "error_b_vs_reference.png", "flip_b_vs_reference.png"}));
  const auto& png = files[2].second;
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(std::to_integer<int>(png[1]), 'P');
  EXPECT_EQ(std::to_integer<int>(png[2]), 'N');
  const std::string pfm(reinterpret_cast<const char*>(files[3].second.data()), 10);
  EXPECT_EQ(pfm, "PF\n4 2\n-1.");
  // 4×2 floats of 3 channels after the header
  EXPECT_EQ(files[3].second.size(), std::string("PF\n4 2\n-1.0\n").size() + 4 * 2 * 3 * sizeof(float));
}

TEST(AbReportFiles, WithoutAReferenceThereIsNoReferenceImage) {
  AbReport report = sample_report();
  report.renders.pop_back();
  report.comparisons = {Comparison{"B", "A", {}, std::vector<float>(8, 0.5f), {}}};
  std::vector<std::string> names;
  for (const auto& file : ab_report_files(report)) names.push_back(file.first);
  EXPECT_EQ(names, (std::vector<std::string>{"report.json", "report.html", "a.png", "a.pfm", "b.png", "b.pfm", "error_b_vs_a.png"}));
}

TEST(AbReportFiles, LeavesOutAMapOfTheWrongSize) {
  AbReport report = sample_report();
  report.comparisons[0].flip_map.pop_back();
  std::vector<std::string> names;
  for (const auto& file : ab_report_files(report)) names.push_back(file.first);
  EXPECT_EQ(std::count(names.begin(), names.end(), "flip_a_vs_reference.png"), 0);
  EXPECT_EQ(std::count(names.begin(), names.end(), "error_a_vs_reference.png"), 1);
  EXPECT_FALSE(Json::parse(ab_report_json(report))["comparisons"][0]["heatmaps"].contains("flip"));
  EXPECT_EQ(ab_report_html(report).find("data-layer=\"flip-a-vs-reference\""), std::string::npos);
}

TEST(DisplayImage, ThePercentileLuminanceMapsToTheKeyValue) {
  RgbImage key = flat_image(10, 10, 0.0f, 2.0f, 0.0f);  // luminance 0.7152 × 2
  key.rgb[1] = 1000.0f;                                  // one bright pixel above the 99th percentile
  EXPECT_DOUBLE_EQ(display_exposure(key), kDisplayKeyValue / (0.7152 * 2.0));
  EXPECT_EQ(display_exposure(flat_image(2, 2, 0, 0, 0)), 1.0);
  EXPECT_EQ(display_exposure(RgbImage{}), 1.0);
}

TEST(DisplayImage, EncodesSrgbAndMarksNonFinitePixels) {
  RgbImage image = flat_image(3, 1, 0.5f, 0.0f, 2.0f);
  image.rgb[3] = std::numeric_limits<float>::quiet_NaN();
  image.rgb[8] = std::numeric_limits<float>::infinity();
  const Rgba8Image shown = display_image(image, 0.5);
  // 0.25 linear → sRGB 0.5371 (IEC 61966-2-1) → 137; 1.0 → 255
  EXPECT_EQ(std::vector<int>(shown.rgba.begin(), shown.rgba.begin() + 4), (std::vector<int>{137, 0, 255, 255}));
  EXPECT_EQ(std::vector<int>(shown.rgba.begin() + 4, shown.rgba.begin() + 8), (std::vector<int>{255, 0, 255, 255}));
  EXPECT_EQ(std::vector<int>(shown.rgba.begin() + 8, shown.rgba.begin() + 12), (std::vector<int>{255, 0, 255, 255}));
}

// Matplotlib's maps (BIDS/colormap) at 0, ½ and 1: viridis #440154, #21918c, #fde725;
// magma #000004, #b73779, #fcfdbf. The polynomial fit stays within 5/255 of them
// (measured: 4.8/255 at magma's top, blue).
TEST(Heatmap, ColourMapsEndWhereMatplotlibsDo) {
  auto near = [](const std::array<double, 3>& colour, std::array<int, 3> expected) {
    for (int c = 0; c < 3; ++c) {
      if (std::abs(colour[size_t(c)] * 255.0 - expected[size_t(c)]) > 5.0) return false;
    }
    return true;
  };
  EXPECT_TRUE(near(colour_at(ColourMap::viridis, 0), {0x44, 0x01, 0x54}));
  EXPECT_TRUE(near(colour_at(ColourMap::viridis, 0.5), {0x21, 0x91, 0x8c}));
  EXPECT_TRUE(near(colour_at(ColourMap::viridis, 1), {0xfd, 0xe7, 0x25}));
  EXPECT_TRUE(near(colour_at(ColourMap::magma, 0), {0x00, 0x00, 0x04}));
  EXPECT_TRUE(near(colour_at(ColourMap::magma, 0.5), {0xb7, 0x37, 0x79}));
  EXPECT_TRUE(near(colour_at(ColourMap::magma, 1), {0xfc, 0xfd, 0xbf}));
  EXPECT_TRUE(near(colour_at(ColourMap::magma, 7), {0xfc, 0xfd, 0xbf})) << "clamped";
}

TEST(Heatmap, MapsTheRangeAndAddsTheBar) {
  const std::vector<float> values = {0.0f, 2.0f, std::numeric_limits<float>::infinity(), 1.0f};
  const HeatmapRange range = abs_error_range(values);
  EXPECT_EQ(range.min, 0.0);
  EXPECT_EQ(range.max, 2.0);
  const Rgba8Image map = heatmap_image(values, 2, 2, ColourMap::viridis, range);
  const int bottom = int(std::lround(colour_at(ColourMap::viridis, 0)[0] * 255));
  const int top = int(std::lround(colour_at(ColourMap::viridis, 1)[0] * 255));
  const int middle = int(std::lround(colour_at(ColourMap::viridis, 0.5)[0] * 255));
  EXPECT_EQ(map.rgba[0], bottom);  // 0 → the bottom of the map
  EXPECT_EQ(map.rgba[4], top);     // 2 → the top
  EXPECT_EQ(map.rgba[12], middle);
  EXPECT_EQ(std::vector<int>(map.rgba.begin() + 8, map.rgba.begin() + 11), (std::vector<int>{0, 255, 255}));
  const Rgba8Image with_bar = with_colour_bar(map, ColourMap::viridis, range);  // too small for labels
  EXPECT_EQ(with_bar.height, 2u);
  EXPECT_EQ(with_bar.width, 2u + 4u + 6u);
  const size_t top_right = 4 * (with_bar.width - 1), bottom_right = 4 * (2 * with_bar.width - 1);
  EXPECT_EQ(with_bar.rgba[top_right], top) << "the bar's top is the range's max";
  EXPECT_EQ(with_bar.rgba[bottom_right], bottom);
}

TEST(Heatmap, LabelsTheBarsEndsWhenTallEnough) {
  const Rgba8Image map = heatmap_image(std::vector<float>(64 * 36, 0.5f), 64, 36, ColourMap::magma, kFlipRange);
  const Rgba8Image with_bar = with_colour_bar(map, ColourMap::magma, kFlipRange);
  EXPECT_GT(with_bar.width, 64u + 4u + 6u) << "a column for the labels";
  const uint32_t labels_x = 64 + 4 + 6 + 4;
  size_t lit_top = 0, lit_bottom = 0;
  for (uint32_t y = 0; y < 36; ++y) {
    for (uint32_t x = labels_x; x < with_bar.width; ++x) {
      const bool lit = with_bar.rgba[4 * (size_t(y) * with_bar.width + x)] > 128;
      (y < 18 ? lit_top : lit_bottom) += lit ? 1 : 0;
    }
  }
  EXPECT_GT(lit_top, 5u) << "\"1\" at the top";
  EXPECT_GT(lit_bottom, 5u) << "\"0\" at the bottom";
}

}  // namespace
}  // namespace volgraph::compare
