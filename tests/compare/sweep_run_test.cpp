// The sweep loop with a fake runner (no device): resume, failed points, the aggregates
// after each point, the progress text; the job list and the merge of sweep folders.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "tests/compare/test_files.h"
#include "graph/diagnostics.h"
#include "tools/compare/sweep_folder.h"
#include "tools/compare/sweep_results.h"
#include "tools/output_files.h"

namespace volgraph::compare {
namespace {

using test_files::read;
using test_files::TempDir;

SweepSpec spec_of(int points) {
  SweepSpec spec;
  spec.file = "configs/sweeps/fake.json";
  spec.config = "configs/demo_fog.json";
  spec.metric = "rel_rmse";
  for (int i = 0; i < points; ++i) {
    SweepPoint p;
    p.id = "p" + std::to_string(i);
    p.series = "s";
    p.label = "slices=" + std::to_string(16 << i);
    p.settings = {{"fog_media.slices", std::to_string(16 << i)}};
    spec.points.push_back(p);
  }
  return spec;
}

// Renders nothing: point i takes 12.3 × (i + 1) ms with error 0.0123 / (i + 1).
struct FakeRunner {
  int calls = 0;
  std::map<std::string, std::string> failures;  // id → message
  std::vector<std::string> ran;

  PointResult operator()(const SweepPoint& point) {
    ++calls;
    ran.push_back(point.id);
    if (failures.count(point.id)) throw std::runtime_error(failures[point.id]);
    const int i = std::stoi(point.id.substr(1));
    PointResult r;
    r.ok = true;
    r.device = "llvmpipe (LLVM 15.0.6, 256 bits)";
    r.device_is_cpu = true;
    r.timing.frame_wall_ms = {12.3 * (i + 1), 12.0 * (i + 1), 13.0 * (i + 1), 3};
    r.metrics.relative_rmse = 0.0123 / (i + 1);
    r.seconds = 4.1;
    return r;
  }
};

PointRunner runner_of(FakeRunner& fake) {
  return [&fake](const SweepPoint& p) { return fake(p); };
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(SweepRun, RunsEveryPointAndSavesEach) {
  TempDir dir;
  FakeRunner fake;
  std::ostringstream progress;
  const SweepSummary summary = run_sweep(spec_of(3), dir.path, runner_of(fake), progress, false);
  EXPECT_EQ(fake.calls, 3);
  EXPECT_EQ(summary.ran, 3);
  EXPECT_EQ(summary.skipped, 0);
  EXPECT_EQ(summary.failed, 0);
  const std::vector<PointResult> results = read_results(dir.path);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[1].id, "p1");
  EXPECT_EQ(results[1].label, "slices=32");  // the spec's identity, not the runner's
  EXPECT_EQ(results[1].settings, spec_of(3).points[1].settings);
  EXPECT_EQ(results[1].metric, "rel_rmse");
  const auto json = nlohmann::json::parse(read(dir.path + "/results.json"));
  EXPECT_EQ(json["points"].size(), 3u);
}

TEST(SweepRun, ResumeRunsOnlyTheMissingPoints) {
  TempDir dir;
  FakeRunner first;
  std::ostringstream progress;
  run_sweep(spec_of(2), dir.path, runner_of(first), progress, false);  // as if stopped after two points
  EXPECT_EQ(first.calls, 2);
  FakeRunner second;
  std::ostringstream resumed;
  const SweepSummary summary = run_sweep(spec_of(5), dir.path, runner_of(second), resumed, false);
  EXPECT_EQ(second.calls, 3);
  EXPECT_EQ(second.ran, (std::vector<std::string>{"p2", "p3", "p4"}));
  EXPECT_EQ(summary.skipped, 2);
  EXPECT_EQ(summary.ran, 3);
  EXPECT_NE(resumed.str().find("resuming: 2 of 5 points already in"), std::string::npos) << resumed.str();
  FakeRunner third;
  std::ostringstream done;
  EXPECT_EQ(run_sweep(spec_of(5), dir.path, runner_of(third), done, false).skipped, 5);
  EXPECT_EQ(third.calls, 0);
  EXPECT_EQ(nlohmann::json::parse(read(dir.path + "/results.json"))["points"].size(), 5u);
}

TEST(SweepRun, FailingPointIsSavedAsFailedAndTheRestRun) {
  TempDir dir;
  FakeRunner fake;
  fake.failures["p1"] = "fog_media.slices: the device has too little memory";
  std::ostringstream progress;
  const SweepSummary summary = run_sweep(spec_of(3), dir.path, runner_of(fake), progress, false);
  EXPECT_EQ(fake.calls, 3);
  EXPECT_EQ(summary.failed, 1);
  EXPECT_EQ(summary.ran, 3);
  const std::vector<PointResult> results = read_results(dir.path);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_FALSE(results[1].ok);
  EXPECT_EQ(results[1].error, "fog_media.slices: the device has too little memory");
  EXPECT_EQ(results[1].label, "slices=32");
  EXPECT_EQ(results[1].settings, spec_of(3).points[1].settings);
  EXPECT_TRUE(results[0].ok && results[2].ok);
  FakeRunner again;
  run_sweep(spec_of(3), dir.path, runner_of(again), progress, false);
  EXPECT_EQ(again.calls, 0) << "a failed point is done: delete its file to run it again";
}

TEST(SweepRun, AggregatesHoldEveryFinishedPointWhenTheNextStarts) {
  TempDir dir;
  FakeRunner fake;
  std::vector<size_t> seen;
  const PointRunner runner = [&](const SweepPoint& p) {
    std::error_code ec;
    const bool have = std::filesystem::exists(dir.path + "/results.json", ec);
    seen.push_back(have ? nlohmann::json::parse(read(dir.path + "/results.json"))["points"].size() : 0);
    EXPECT_EQ(read_results(dir.path).size(), seen.back());
    return fake(p);
  };
  std::ostringstream progress;
  run_sweep(spec_of(4), dir.path, runner, progress, false);
  EXPECT_EQ(seen, (std::vector<size_t>{0, 1, 2, 3}));
}

TEST(SweepRun, PlainProgressIsOneLineAPoint) {
  TempDir dir;
  FakeRunner fake;
  fake.failures["p2"] = "boom";
  std::ostringstream progress;
  run_sweep(spec_of(3), dir.path, runner_of(fake), progress, false);
  EXPECT_EQ(lines_of(progress.str()), (std::vector<std::string>{"[1/3] slices=16: 12.3 ms, rel_rmse 0.0123 (4.1 s)",
                                                                "[2/3] slices=32: 24.6 ms, rel_rmse 0.00615 (4.1 s)",
                                                                "[3/3] slices=64: FAILED: boom"}));
  EXPECT_EQ(progress.str().find('\r'), std::string::npos);
}

TEST(SweepRun, PlainProgressNamesTheSeriesWhenThereAreSeveral) {
  TempDir dir;
  FakeRunner fake;
  SweepSpec spec = spec_of(2);
  spec.points[1].series = "hillaire";
  std::ostringstream progress;
  run_sweep(spec, dir.path, runner_of(fake), progress, false);
  EXPECT_EQ(lines_of(progress.str()),
            (std::vector<std::string>{"[1/2] s: slices=16: 12.3 ms, rel_rmse 0.0123 (4.1 s)",
                                      "[2/2] hillaire: slices=32: 24.6 ms, rel_rmse 0.00615 (4.1 s)"}));
}

TEST(SweepRun, TerminalProgressRedrawsOneLineWithAnEstimate) {
  TempDir dir;
  FakeRunner fake;
  fake.failures["p1"] = "boom";
  std::ostringstream progress;
  run_sweep(spec_of(3), dir.path, runner_of(fake), progress, true);
  const std::string text = progress.str();
  EXPECT_NE(text.find("\r[--------"), std::string::npos) << text;
  EXPECT_TRUE(
      std::regex_search(text, std::regex(R"(\r\[#{8}-{16}\] 1/3 points  \d+:\d\d elapsed, ~\d+:\d\d left  slices=16)")))
      << text;
  EXPECT_NE(text.find("\r[########################] 3/3 points"), std::string::npos) << text;
  EXPECT_NE(text.find("\r\x1b[K[2/3] slices=32: FAILED: boom\n"), std::string::npos)
      << text;  // failures stay on screen
  EXPECT_EQ(text.find("[1/3] slices=16: 12.3 ms"), std::string::npos) << "no plain lines for points that worked";
  EXPECT_EQ(text.back(), '\n');
}

TEST(SweepJobs, OneCommandALineAndAManifest) {
  TempDir dir;
  const SweepSpec spec = spec_of(3);
  write_jobs(dir.path + "/jobs", spec, [](const SweepPoint& p) {
    return "volgraph sweep configs/sweeps/fake.json --point " + p.id + " -o 'out dir'";
  });
  EXPECT_EQ(read(dir.path + "/jobs/jobs.txt"),
            "volgraph sweep configs/sweeps/fake.json --point p0 -o 'out dir'\n"
            "volgraph sweep configs/sweeps/fake.json --point p1 -o 'out dir'\n"
            "volgraph sweep configs/sweeps/fake.json --point p2 -o 'out dir'\n");
  const auto manifest = nlohmann::json::parse(read(dir.path + "/jobs/manifest.json"));
  EXPECT_EQ(manifest["spec"], "configs/sweeps/fake.json");
  EXPECT_EQ(manifest["config"], "configs/demo_fog.json");
  EXPECT_EQ(manifest["count"], 3);
  EXPECT_EQ(manifest["points"][1]["id"], "p1");
  EXPECT_EQ(manifest["points"][1]["label"], "slices=32");
  EXPECT_EQ(manifest["points"][1]["series"], "s");
  EXPECT_EQ(manifest["points"][1]["command"], "volgraph sweep configs/sweeps/fake.json --point p1 -o 'out dir'");
  EXPECT_THROW(write_jobs(dir.path, spec, [](const SweepPoint&) { return std::string("a\nb"); }),
               std::invalid_argument);
}

PointResult done_point(const std::string& id, const std::string& device, double ms) {
  PointResult r;
  r.id = id;
  r.series = "s";
  r.label = id;
  r.ok = true;
  r.device = device;
  r.metric = "rel_rmse";
  r.timing.frame_wall_ms = {ms, ms, ms, 3};
  r.metrics.relative_rmse = 1 / ms;
  return r;
}

std::map<std::string, std::string> files_of(const std::string& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) files[std::filesystem::relative(entry.path(), dir).string()] = read(entry.path());
  }
  return files;
}

TEST(SweepMerge, KeepsOneCopyADeviceAndIsByteIdenticalOnRepeat) {
  TempDir a, b, c, out;
  save_point(a.path, done_point("p0", "gpu X", 1));
  save_point(a.path, done_point("p1", "gpu X", 2));
  save_point(b.path, done_point("p1", "gpu X", 2));  // the same copy twice: one
  save_point(b.path, done_point("p2", "gpu X", 3));
  save_point(c.path, done_point("p1", "gpu Y", 5));  // another device: both kept
  const SweepSpec spec = spec_of(3);
  merge_results({a.path, b.path, c.path}, out.path, &spec);
  const auto first = files_of(out.path);
  std::vector<std::string> points;
  for (const auto& [name, bytes] : first) {
    if (name.rfind("points/", 0) == 0) points.push_back(name);
  }
  std::vector<std::string> expected = {"points/p0.json", "points/p1@" + device_hash("gpu X") + ".json",
                                       "points/p1@" + device_hash("gpu Y") + ".json", "points/p2.json"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(points, expected);
  EXPECT_EQ(device_hash("gpu X").size(), 8u);
  const auto json = nlohmann::json::parse(first.at("results.json"));
  ASSERT_EQ(json["points"].size(), 4u);
  EXPECT_EQ(json["points"][1]["id"], "p1");
  EXPECT_EQ(json["points"][2]["id"], "p1");
  EXPECT_EQ(json["devices"].size(), 2u);
  EXPECT_EQ(json["devices"][1]["pareto"], nlohmann::json::array({"p1"}));  // gpu Y's only point, however slow

  merge_results({a.path, b.path, c.path}, out.path, &spec);
  EXPECT_EQ(files_of(out.path), first);
  merge_results({out.path}, out.path, &spec);  // into itself
  EXPECT_EQ(files_of(out.path), first);
}

TEST(SweepMerge, DifferingCopiesOfOneDeviceKeepTheFirstDirs) {
  TempDir a, b, out;
  save_point(a.path, done_point("p0", "gpu X", 1));
  save_point(b.path, done_point("p0", "gpu X", 7));
  merge_results({a.path, b.path}, out.path, nullptr);
  const std::vector<PointResult> merged = read_results(out.path);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].timing.frame_wall_ms.median, 1);
  EXPECT_EQ(nlohmann::json::parse(read(out.path + "/results.json"))["metric"], "rel_rmse");
}

TEST(SweepMerge, PointOfAnotherDeviceSplitsTheOutputsCopy) {
  TempDir a, out;
  save_point(out.path, done_point("p0", "gpu X", 1));
  save_point(a.path, done_point("p0", "gpu Y", 2));
  merge_results({a.path}, out.path, nullptr);
  EXPECT_FALSE(std::filesystem::exists(out.path + "/points/p0.json"));
  EXPECT_TRUE(std::filesystem::exists(out.path + "/points/p0@" + device_hash("gpu X") + ".json"));
  EXPECT_TRUE(std::filesystem::exists(out.path + "/points/p0@" + device_hash("gpu Y") + ".json"));
  EXPECT_EQ(read_results(out.path).size(), 2u);
}


// A folder belongs to one sweep: another spec on the same config, or other settings, is
// refused naming both; the same spec and settings resume.
TEST(SweepFolder, RefusesAnotherSpecOrSettings) {
  TempDir dir;
  const SweepSpec first = spec_of(2);
  claim_sweep_folder(first, dir.path);
  EXPECT_NO_THROW(claim_sweep_folder(first, dir.path));
  SweepSpec other_spec = first;
  other_spec.file = "configs/sweeps/other.json";
  try {
    claim_sweep_folder(other_spec, dir.path);
    FAIL() << "another spec's sweep was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("fake.json against"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("other.json"), std::string::npos) << e.what();
  }
  for (auto change : {+[](SweepSpec& s) { s.runs = 9; }, +[](SweepSpec& s) { s.warmup = 3; },
                      +[](SweepSpec& s) { s.size = {16, 9, 1}; }, +[](SweepSpec& s) { s.config = "configs/demo_x.json"; },
                      +[](SweepSpec& s) { s.metric = "flip"; }, +[](SweepSpec& s) { s.mask = "fog_only"; }}) {
    SweepSpec changed = first;
    change(changed);
    EXPECT_THROW(claim_sweep_folder(changed, dir.path), ConfigError);
  }
}

// Points without a recorded sweep, or an empty record beside points: not a sweep folder
// to add to. An empty record in an empty folder (a failed write) does not block a rerun.
TEST(SweepFolder, PointsWithoutIdentityAreRefusedAnEmptyRecordIsNot) {
  TempDir dir;
  std::ofstream(std::filesystem::path(dir.path) / "sweep_settings.txt").close();
  EXPECT_NO_THROW(claim_sweep_folder(spec_of(1), dir.path));
  EXPECT_EQ(read(std::filesystem::path(dir.path) / "sweep_settings.txt"), sweep_identity_text(spec_of(1)));
  TempDir bare;
  save_point(bare.path, PointResult{"p0"});
  EXPECT_THROW(claim_sweep_folder(spec_of(1), bare.path), ConfigError);
  std::ofstream(std::filesystem::path(bare.path) / "sweep_settings.txt").close();
  EXPECT_THROW(claim_sweep_folder(spec_of(1), bare.path), ConfigError);
}

// A merge takes the folders of one sweep; the SPEC given must be theirs; without SPEC the
// figures (size, runs, warm-up) are the folders'.
TEST(SweepFolder, MergeTakesOneSweepAndReadsItsFigures) {
  TempDir a, b, c, out;
  SweepSpec spec = spec_of(2);
  spec.size = {32, 18, 1};
  spec.runs = 3;
  spec.warmup = 2;
  claim_sweep_folder(spec, a.path);
  claim_sweep_folder(spec, b.path);
  SweepSpec other = spec;
  other.file = "configs/sweeps/other.json";
  claim_sweep_folder(other, c.path);
  const std::string identity = common_sweep_identity({a.path, b.path}, out.path, nullptr);
  EXPECT_EQ(identity, sweep_identity_text(spec));
  const SweepSpec back = spec_of_identity(identity);
  EXPECT_EQ(back.size, spec.size);
  EXPECT_EQ(back.runs, 3);
  EXPECT_EQ(back.warmup, 2);
  EXPECT_EQ(sweep_identity_text(back), identity);
  EXPECT_THROW(common_sweep_identity({a.path, c.path}, out.path, nullptr), ConfigError);
  EXPECT_THROW(common_sweep_identity({a.path}, out.path, &other), ConfigError);
  claim_sweep_folder(other, out.path);
  EXPECT_THROW(common_sweep_identity({a.path}, out.path, nullptr), ConfigError);
  TempDir empty;
  EXPECT_THROW(common_sweep_identity({a.path, empty.path}, out.path, nullptr), ConfigError);
}

// No output may be an input: the same file by another name ("..", a link) is caught, a
// file of the output folder with no output's name is not.
TEST(OutputsNotInputs, ComparesCanonicalPaths) {
  TempDir dir;
  const std::filesystem::path out(dir.path);
  std::filesystem::create_directories(out / "sub" / "points");
  std::ofstream(out / "sub" / "results.json") << "{}";
  std::filesystem::create_symlink(out / "sub" / "results.json", out / "link.json");
  const std::string sub = (out / "sub").string();
  const std::vector<std::string> names = {"results.json"};
  EXPECT_THROW(check_outputs_not_inputs({{"the spec", sub + "/results.json"}}, "-o", sub, names), ConfigError);
  EXPECT_THROW(check_outputs_not_inputs({{"the spec", (out / "link.json").string()}}, "-o", dir.path + "/sub/../sub", names), ConfigError);
  EXPECT_THROW(check_outputs_not_inputs({{"the spec", sub + "/points/x.json"}}, "-o", sub, names, {"points"}), ConfigError);
  EXPECT_NO_THROW(check_outputs_not_inputs({{"the spec", sub + "/spec.json"}, {"none", ""}, {"ref", "cpu"}}, "-o", sub, names, {"points"}));
  try {
    check_outputs_not_inputs({{"the spec", sub + "/results.json"}}, "-o", sub, names);
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("would overwrite the spec"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volgraph::compare
