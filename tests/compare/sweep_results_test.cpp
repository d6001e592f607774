// A sweep point's file (every field, non-finite figures), the points folder, the
// Pareto front per device, and the aggregate files (results.json, results.csv, the
// report and its plot).
#include "tests/compare/test_files.h"
#include "tools/compare/sweep_results.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "graph/diagnostics.h"
#include "tools/compare/sweep_report.h"

namespace volgraph::compare {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

using test_files::read;
using test_files::TempDir;

PointResult point(const std::string& id, const std::string& device, double ms, double error,
                  const std::string& series = "s") {
  PointResult p;
  p.id = id;
  p.series = series;
  p.label = "label " + id;
  p.device = device;
  p.ok = true;
  p.metric = "rel_rmse";
  p.timing.frame_wall_ms = {ms, ms * 0.9, ms * 1.2, 5};
  p.timing.runs = 5;
  p.metrics.relative_rmse = error;
  p.settings = {{"fog_media.slices", "64"}};
  return p;
}

PointResult full_point() {
  PointResult p;
  p.id = "0123456789ab";
  p.series = "wronski";
  p.label = "fog_media.slices=64, fog_integral=hillaire";
  p.graph = "configs/graphs/raymarch_fog.json";
  p.settings = {{"z.last", "1"}, {"fog_integral", "\"hillaire\""}, {"a.first", "[1, 2]"}};
  p.ok = true;
  p.error = "";
  p.backend = "vulkan";
  p.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
  p.driver = "Mesa 22.3.6";
  p.device_is_cpu = true;
  p.command = "volgraph render configs/demo_fog.json --set 'fog_media.slices=64'";
  p.timing.runs = 5;
  p.timing.warmup = 1;
  p.timing.frame_wall_ms = {12.5, 11.25, 14.0625, 5};
  p.timing.passes = {{"fog_media", "froxel_voxelize", {1.5, 1.25, 2, 5}, {0.125, 0.1, 0.2, 5}},
                     {"fog_integral", "scatter_integrate", {0.75, 0.5, 1, 5}, {0.0625, 0.05, 0.08, 5}}};
  p.timing.gpu_timestamps = true;
  p.timing.clock = "lavapipe (CPU): time stamps are CPU time";
  p.memory = {1000, 2000, 900, 300, 7, 2};
  p.metrics.compared_pixels = 14400;
  p.metrics.nan_values = 3;
  p.metrics.inf_values = 4;
  p.metrics.rmse = 0.1;
  p.metrics.relative_rmse = 0.0123;
  p.metrics.psnr_db = inf;
  p.metrics.ssim = nan;
  p.metrics.flip = -inf;
  p.metrics.max_abs_error = 1.0 / 3;
  p.metrics.relative_mean_error = 1e-300;
  p.metric = "rel_rmse";
  p.seconds = 4.125;
  p.pareto = true;
  return p;
}

void expect_same_spread(const Spread& a, const Spread& b) {
  EXPECT_EQ(a.median, b.median);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.runs, b.runs);
}

TEST(SweepResults, JsonRoundTripKeepsEveryFieldAndNonFiniteFigures) {
  const PointResult p = full_point();
  const std::string text = point_result_json(p);
  const PointResult q = parse_point_result(text, "p.json");
  EXPECT_EQ(q.id, p.id);
  EXPECT_EQ(q.series, p.series);
  EXPECT_EQ(q.label, p.label);
  EXPECT_EQ(q.graph, p.graph);
  EXPECT_EQ(q.settings, p.settings);  // in the order written, not sorted
  EXPECT_EQ(q.ok, p.ok);
  EXPECT_EQ(q.error, p.error);
  EXPECT_EQ(q.backend, p.backend);
  EXPECT_EQ(q.device, p.device);
  EXPECT_EQ(q.driver, p.driver);
  EXPECT_EQ(q.device_is_cpu, p.device_is_cpu);
  EXPECT_EQ(q.command, p.command);
  EXPECT_EQ(q.timing.runs, 5);
  EXPECT_EQ(q.timing.warmup, 1);
  expect_same_spread(q.timing.frame_wall_ms, p.timing.frame_wall_ms);
  ASSERT_EQ(q.timing.passes.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(q.timing.passes[i].pass, p.timing.passes[i].pass);
    EXPECT_EQ(q.timing.passes[i].type, p.timing.passes[i].type);
    expect_same_spread(q.timing.passes[i].gpu_ms, p.timing.passes[i].gpu_ms);
    expect_same_spread(q.timing.passes[i].cpu_ms, p.timing.passes[i].cpu_ms);
  }
  EXPECT_TRUE(q.timing.gpu_timestamps);
  EXPECT_EQ(q.timing.clock, p.timing.clock);
  EXPECT_EQ(q.memory.aliased_bytes, 1000u);
  EXPECT_EQ(q.memory.unaliased_bytes, 2000u);
  EXPECT_EQ(q.memory.lower_bound_bytes, 900u);
  EXPECT_EQ(q.memory.persistent_bytes, 300u);
  EXPECT_EQ(q.memory.passes_run, 7u);
  EXPECT_EQ(q.memory.passes_culled, 2u);
  EXPECT_EQ(q.metrics.compared_pixels, 14400u);
  EXPECT_EQ(q.metrics.nan_values, 3u);
  EXPECT_EQ(q.metrics.inf_values, 4u);
  EXPECT_EQ(q.metrics.rmse, 0.1);
  EXPECT_EQ(q.metrics.relative_rmse, 0.0123);
  EXPECT_EQ(q.metrics.psnr_db, inf);
  EXPECT_TRUE(std::isnan(q.metrics.ssim));
  EXPECT_EQ(q.metrics.flip, -inf);
  EXPECT_EQ(q.metrics.max_abs_error, 1.0 / 3);  // every digit kept
  EXPECT_EQ(q.metrics.relative_mean_error, 1e-300);
  EXPECT_EQ(q.metric, "rel_rmse");
  EXPECT_EQ(q.seconds, 4.125);
  EXPECT_TRUE(q.pareto);
  EXPECT_EQ(point_result_json(q), text);
}

TEST(SweepResults, NonFiniteFiguresAreWrittenAsStrings) {
  const std::string text = point_result_json(full_point());
  EXPECT_NE(text.find("\"psnr_db\": \"inf\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"ssim\": \"nan\""), std::string::npos);
  EXPECT_NE(text.find("\"flip\": \"-inf\""), std::string::npos);
  EXPECT_NO_THROW((void)nlohmann::json::parse(text));  // strict JSON: no Infinity or NaN literals
}

TEST(SweepResults, ParseErrorsNameTheFileAndTheValue) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(point_result_json(full_point()));
  j["timing"]["frame_wall_ms"]["median"] = "fast";
  try {
    parse_point_result(j.dump(), "dir/points/x.json");
    FAIL() << "accepted a string median";
  } catch (const ConfigError& e) {  // bad input (exit 2), not an internal error
    EXPECT_NE(std::string(e.what()).find("dir/points/x.json: error at /timing/frame_wall_ms/median: expected a number"),
              std::string::npos)
        << e.what();
  }
  j.erase("metrics");
  EXPECT_THROW(parse_point_result(j.dump(), "x.json"), ConfigError);
  try {
    parse_point_result("{\"id\": \"ab", "dir/points/cut.json");
    FAIL() << "accepted a truncated file";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("dir/points/cut.json: error: not JSON"), std::string::npos) << e.what();
  }
}

TEST(SweepResults, SavedPointsReadBackSortedByIdWithoutTemporaries) {
  TempDir dir;
  for (const char* id : {"cc", "aa", "bb"}) save_point(dir.path, point(id, "d", 1, 0.1));
  std::ofstream(dir.path + "/points/dd.json.tmp-123") << "{";
  std::ofstream(dir.path + "/points/ee.json.tmp-123-0.json") << "{";
  std::ofstream(dir.path + "/points/notes.txt") << "not a point";
  const std::vector<PointResult> results = read_results(dir.path);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[0].id, "aa");
  EXPECT_EQ(results[1].id, "bb");
  EXPECT_EQ(results[2].id, "cc");
  for (const auto& entry : std::filesystem::directory_iterator(dir.path + "/points")) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-" + std::to_string(::getpid())), std::string::npos)
        << "save_point left " << entry.path();
  }
}

TEST(SweepResults, PointFileNeverClaimsTheFront) {
  TempDir dir;
  PointResult p = point("aa", "d", 1, 0.1);
  p.pareto = true;
  save_point(dir.path, p);
  EXPECT_FALSE(read_results(dir.path).at(0).pareto);
}

TEST(SweepResults, CorruptPointFileIsAnErrorNamingIt) {
  TempDir dir;
  save_point(dir.path, point("aa", "d", 1, 0.1));
  std::ofstream(dir.path + "/points/bb.json") << "{\"id\": \"bb\"";
  try {
    read_results(dir.path);
    FAIL() << "read a corrupt point file";
  } catch (const ConfigError& e) {  // a damaged folder is bad input (exit 2)
    EXPECT_NE(std::string(e.what()).find("points/bb.json"), std::string::npos) << e.what();
  }
}

// Every damage a sweep folder can take is bad input naming the file: a point file cut
// short, one missing a field, empty, a folder under a point's name, `points` a file.
TEST(SweepResults, DamagedFoldersAreBadInput) {
  const std::string whole = point_result_json(point("aa", "d", 1, 0.1));
  nlohmann::ordered_json missing = nlohmann::ordered_json::parse(whole);
  missing.erase("timing");
  for (const std::string& text : {whole.substr(0, whole.size() / 2), missing.dump(), std::string(), std::string("[]")}) {
    TempDir dir;
    std::filesystem::create_directories(dir.path + "/points");
    std::ofstream(dir.path + "/points/aa.json") << text;
    EXPECT_THROW(read_results(dir.path), ConfigError) << text;
  }
  TempDir file;
  std::ofstream(file.path + "/points") << "not a folder";
  EXPECT_THROW(read_results(file.path), ConfigError);
  TempDir out;
  EXPECT_THROW(merge_results({file.path}, out.path, nullptr), ConfigError);
}

TEST(SweepResults, NoPointsFolderIsNoResults) {
  TempDir dir;
  EXPECT_TRUE(read_results(dir.path).empty());
  EXPECT_TRUE(read_results(dir.path + "/absent").empty());
}

TEST(SweepResults, IdThatWouldLeaveThePointsFolderIsRefused) {
  TempDir dir;
  EXPECT_THROW(save_point(dir.path, point("../x", "d", 1, 0.1)), std::invalid_argument);
  EXPECT_THROW(save_point(dir.path, point("", "d", 1, 0.1)), std::invalid_argument);
}

std::vector<std::string> front_of(const std::vector<PointResult>& results) {
  std::vector<std::string> ids;
  for (const PointResult& p : results) {
    if (p.pareto) ids.push_back(p.id);
  }
  return ids;
}

TEST(SweepPareto, KnownSetPerDevice) {
  std::vector<PointResult> r = {
      point("a_fast", "A", 0.5, 0.9),   // fastest: front
      point("a1", "A", 1, 0.5),         // front
      point("a2", "A", 2, 0.2),         // front
      point("a2_tie", "A", 2, 0.2),     // equal to a2 in both: both on the front
      point("a3", "A", 3, 0.3),         // a2 is faster and better
      point("a1_worse", "A", 1, 0.6),   // a1 as fast, better
      point("a4_slower", "A", 4, 0.2),  // a2 as good, faster
      point("b1", "B", 10, 0.6),        // a1 would beat it, but times of devices do not compare
      point("b2", "B", 10, 0.7),        // b1 as fast, better
      point("b3", "B", 20, 0.1),        // front
  };
  PointResult failed = point("a_failed", "A", 0.1, 0.0);
  failed.ok = false;
  failed.error = "boom";
  r.push_back(failed);  // never on the front, and beats no one
  PointResult broken = point("a_nan", "A", 0.2, 0.0);
  broken.metrics.nan_values = 12;  // its error leaves out the NaN pixels: not a fair figure
  r.push_back(broken);
  r.push_back(point("a_nan_error", "A", 0.3, nan));
  mark_pareto(r);
  EXPECT_EQ(front_of(r), (std::vector<std::string>{"a_fast", "a1", "a2", "a2_tie", "b1", "b3"}));
}

TEST(SweepPareto, HigherIsBetterMetricTurnsTheComparison) {
  std::vector<PointResult> r = {point("a", "A", 1, 0), point("b", "A", 2, 0), point("c", "A", 3, 0),
                                point("d", "A", 4, 0)};
  const double psnr[] = {30, 40, 35, inf};
  for (size_t i = 0; i < r.size(); ++i) {
    r[i].metric = "psnr";
    r[i].metrics.psnr_db = psnr[i];
  }
  mark_pareto(r);
  EXPECT_EQ(front_of(r), (std::vector<std::string>{"a", "b", "d"}));
}

SweepSpec spec_with(const std::vector<std::string>& ids) {
  SweepSpec spec;
  spec.file = "configs/sweeps/test.json";
  spec.config = "configs/demo_fog.json";
  spec.size = {64, 36, 1};
  spec.metric = "rel_rmse";
  spec.mask = "fog_only";
  for (const std::string& id : ids) {
    SweepPoint p;
    p.id = id;
    p.series = "s";
    p.label = "label " + id;
    spec.points.push_back(p);
  }
  return spec;
}

TEST(SweepCsv, ColumnsQuotingAndSettingKeys) {
  PointResult quoted = point("aa", "llvmpipe, \"quoted\"", 1.5, 0.25);
  quoted.label = "slices=64, \"hillaire\"";
  quoted.settings = {{"fog_media.slices", "64"}, {"fog_integral", "\"hillaire\""}};
  PointResult other = point("bb", "gpu", 2, 0.125);
  other.settings = {{"sun_shadow.resolution", "2048"}};
  PointResult failed = point("cc", "gpu", 0, 0);
  failed.ok = false;
  failed.error = "line one\nline two";
  failed.settings = {};
  std::vector<PointResult> r = {quoted, other, failed};
  mark_pareto(r);
  const std::string csv = results_csv(r);
  std::vector<std::string> lines;
  for (size_t start = 0; start < csv.size();) {
    const size_t end = csv.find("\r\n", start);
    ASSERT_NE(end, std::string::npos) << "every line ends in CRLF";
    lines.push_back(csv.substr(start, end - start));
    start = end + 2;
  }
  ASSERT_EQ(lines.size(), 4u) << csv;
  EXPECT_EQ(
      lines[0],
      "id,series,label,device,ok,error,frame_ms_median,frame_ms_min,frame_ms_max,runs,rmse,rel_rmse,psnr,ssim,flip,"
      "max_abs,rel_mean,nan,inf,pareto,fog_media.slices,fog_integral,sun_shadow.resolution");
  EXPECT_EQ(lines[1],
            "aa,s,\"slices=64, \"\"hillaire\"\"\",\"llvmpipe, "
            "\"\"quoted\"\"\",true,,1.5,1.35,1.7999999999999998,5,0.0,0.25,0.0,1.0,"
            "0.0,0.0,0.0,0,0,true,64,hillaire,");
  EXPECT_EQ(lines[2], "bb,s,label bb,gpu,true,,2.0,1.8,2.4,5,0.0,0.125,0.0,1.0,0.0,0.0,0.0,0,0,true,,,2048");
  EXPECT_EQ(lines[3], "cc,s,label cc,gpu,false,\"line one\nline two\",,,,,,,,,,,,,,false,,,");
}

TEST(SweepMarkdown, OneTableADeviceWithTheRatioToTheFastestAndTheFront) {
  PointResult fast = point("aa", "gpu", 2, 0.25);
  PointResult slow = point("bb", "gpu", 5, 0.125);
  slow.label = "a|b";
  PointResult failed = point("cc", "gpu", 0, 0);
  failed.ok = false;
  failed.error = "line one\nline two";
  PointResult other = point("dd", "llvmpipe (LLVM 15)", 7, 0.5);
  std::vector<PointResult> r = {fast, slow, failed, other};
  mark_pareto(r);
  SweepSpec spec;
  spec.metric = "rel_rmse";
  spec.mask = "fog_only";
  const std::string md = results_markdown(spec, r);
  EXPECT_NE(md.find("On gpu, 160x90, median of 5 frames after 1 warm-up; rel_rmse over fog_only pixels"), std::string::npos) << md;
  EXPECT_NE(md.find("| s | label aa | 2 | 1.8 – 2.4 | 1 | 0.25 | 0 | * |"), std::string::npos) << md;
  EXPECT_NE(md.find("| s | a\\|b | 5 | 4.5 – 6 | 2.5 | 0.125 | 0 | * |"), std::string::npos) << md;
  EXPECT_NE(md.find("| s | label cc | failed: line one line two | | | | | |"), std::string::npos) << md;
  EXPECT_NE(md.find("On llvmpipe (LLVM 15) — lavapipe (CPU)"), std::string::npos) << md;
  EXPECT_NE(md.find("| s | label dd | 7 | 6.3 – 8.4 | 1 | 0.5 | 0 | * |"), std::string::npos) << "a device's ratio is to its own fastest";
}

TEST(SweepAggregates, EveryFileWrittenInSpecOrderWithoutTemporaries) {
  TempDir dir;
  const SweepSpec spec = spec_with({"p2", "p1", "p3"});
  std::vector<PointResult> r = {point("p1", "llvmpipe (LLVM 15)", 1, 0.5), point("p2", "llvmpipe (LLVM 15)", 100, 0.01),
                                point("extra", "llvmpipe (LLVM 15)", 50, 0.6)};
  PointResult failed = point("p3", "llvmpipe (LLVM 15)", 0, 0);
  failed.ok = false;
  failed.error = "the driver <refused>";
  r.push_back(failed);
  write_aggregates(dir.path, spec, r);

  const auto json = nlohmann::json::parse(read(dir.path + "/results.json"));
  EXPECT_EQ(json["spec"], "configs/sweeps/test.json");
  EXPECT_EQ(json["metric"], "rel_rmse");
  EXPECT_EQ(json["mask"], "fog_only");
  EXPECT_EQ(json["size"], nlohmann::json::array({64, 36}));
  ASSERT_EQ(json["points"].size(), 4u);
  EXPECT_EQ(json["points"][0]["id"], "p2");
  EXPECT_EQ(json["points"][1]["id"], "p1");
  EXPECT_EQ(json["points"][2]["id"], "p3");
  EXPECT_EQ(json["points"][3]["id"], "extra");  // not in the spec: after its points
  EXPECT_EQ(json["points"][0]["pareto"], true);
  EXPECT_EQ(json["points"][1]["pareto"], true);
  EXPECT_EQ(json["points"][2]["pareto"], false);
  EXPECT_EQ(json["points"][3]["pareto"], false);
  ASSERT_EQ(json["devices"].size(), 1u);
  EXPECT_EQ(json["devices"][0]["points"], 4);
  EXPECT_EQ(json["devices"][0]["failed"], 1);
  EXPECT_EQ(json["devices"][0]["pareto"], nlohmann::json::array({"p1", "p2"}));  // by time

  const std::string html = read(dir.path + "/report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("lavapipe (CPU)"), std::string::npos);
  EXPECT_NE(html.find("<title>s: label p1"), std::string::npos);
  EXPECT_NE(html.find("the driver &lt;refused&gt;"), std::string::npos);  // failed points with their errors
  EXPECT_NE(html.find("class=\"front\""), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(read(dir.path + "/pareto.svg").rfind("<svg", 0), 0u);
  EXPECT_TRUE(std::filesystem::exists(dir.path + "/results.csv"));
  if (have_svg_converter()) {
    const std::string png = read(dir.path + "/pareto.png");
    EXPECT_EQ(png.substr(0, 8), "\x89PNG\r\n\x1a\n");
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir.path)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name.find(".tmp-") == std::string::npos && name.front() != '.') << "left " << name;
  }
}

TEST(SweepAggregates, NoPngWithoutTheConverterAndTheStaleOneRemoved) {
  TempDir dir;
  std::ofstream(dir.path + "/pareto.png") << "stale";
  write_aggregates(dir.path, spec_with({"p1"}), {point("p1", "gpu", 1, 0.1)}, false);
  EXPECT_FALSE(std::filesystem::exists(dir.path + "/pareto.png"));
  EXPECT_TRUE(std::filesystem::exists(dir.path + "/pareto.svg"));
}

size_t count_of(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(SweepReport, OnePanelAndOneFrontPerDeviceLogAxesWhenSpanning) {
  SweepSpec spec = spec_with({});
  std::vector<PointResult> r = {point("a1", "gpu A", 1, 0.5, "wronski"), point("a2", "gpu A", 100, 0.001, "hillaire"),
                                point("b1", "gpu B", 2, 0.4, "wronski"), point("b2", "gpu B", 3, 0.3, "wronski")};
  mark_pareto(r);
  const std::string svg = pareto_svg(spec, r);
  EXPECT_EQ(count_of(svg, "class=\"panel\""), 2u);
  EXPECT_EQ(count_of(svg, "<polyline class=\"front\""), 2u);  // one a device: never joined across devices
  EXPECT_EQ(count_of(svg, "<circle cx"),
            4u + 5u);  // the points; the legends' swatches: A 2 series + front, B 1 + front
  EXPECT_NE(svg.find("gpu A"), std::string::npos);
  EXPECT_NE(svg.find("gpu B"), std::string::npos);
  EXPECT_NE(svg.find("frame time, ms (median, log scale)"), std::string::npos);  // panel A: 1 … 100 ms
  EXPECT_NE(svg.find("frame time, ms (median)"), std::string::npos);             // panel B: 2 … 3 ms
  EXPECT_NE(svg.find("lower is better, log scale"), std::string::npos);
  EXPECT_NE(svg.find("#4e79a7"), std::string::npos);  // wronski's colour
  EXPECT_NE(svg.find("#f28e2b"), std::string::npos);  // hillaire's
  EXPECT_EQ(svg.find("lavapipe"), std::string::npos);
}

TEST(SweepReport, PointThatFailedBeforeNamingADeviceIsListedApart) {
  PointResult failed;
  failed.id = "p9";
  failed.series = "s";
  failed.label = "fog_media.slices=4096";
  failed.error = "fog_media: 4096 slices exceed the device's 2048";
  std::vector<PointResult> r = {point("p1", "gpu A", 1, 0.5), failed};
  mark_pareto(r);
  const std::string svg = pareto_svg(spec_with({}), r);
  EXPECT_EQ(count_of(svg, "class=\"panel\""), 1u);
  const std::string html = sweep_report_html(spec_with({"p1", "p9"}), r, svg);
  EXPECT_EQ(html.find("(device unknown)"), std::string::npos);
  EXPECT_NE(html.find("<h2>Failed points</h2>"), std::string::npos);
  EXPECT_NE(html.find("<b>s: fog_media.slices=4096</b> (<code>p9</code>): <pre>fog_media: 4096 slices exceed the "
                      "device&#39;s 2048</pre>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("2 of the spec's 2 done"), std::string::npos);
}

TEST(SweepReport, NoPointYetIsAnEmptyPlot) {
  const std::string svg = pareto_svg(spec_with({"p1"}), {});
  EXPECT_NE(svg.find("no point rendered yet"), std::string::npos);
  EXPECT_EQ(count_of(svg, "class=\"panel\""), 0u);
}

}  // namespace
}  // namespace volgraph::compare
