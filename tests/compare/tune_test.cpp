// Tuning: the fastest point under an error budget on a sweep built by hand (at the budget
// counts as under; failed points and NaN images never win), the faster points that lost,
// the flags, and the overlay loaded back as a config.
#include "tools/compare/tune.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph::compare {
namespace {

using Settings = std::vector<std::pair<std::string, std::string>>;

PointResult point(const std::string& id, double median_ms, double rel_rmse, Settings settings = {}, bool ok = true,
                  const std::string& device = "llvmpipe (LLVM 15.0.6, 256 bits)") {
  PointResult r;
  r.id = id;
  r.series = "froxel";
  r.label = id;
  r.settings = std::move(settings);
  r.ok = ok;
  r.device = device;
  r.timing.frame_wall_ms = Spread{median_ms, median_ms - 0.1, median_ms + 0.1, 5};
  r.timing.runs = 5;
  r.metrics.relative_rmse = rel_rmse;
  r.metric = "rel_rmse";
  return r;
}

const Settings kHillaire32{{"sun_shadow.resolution", "1024"}, {"fog_integral", "\"hillaire\""}, {"fog_media.slices", "32"}};

// Budget 0.05: a and b are faster and over it, c sits exactly at it, d is under and slower,
// e failed (fastest, no error), f is over and slower.
std::vector<PointResult> known_sweep() {
  return {point("a", 2, 0.20), point("b", 3, 0.08), point("c", 4, 0.05, kHillaire32), point("d", 6, 0.01),
          point("e", 1, 0.0, {}, false), point("f", 8, 0.5)};
}

std::vector<std::string> ids(const std::vector<PointResult>& results) {
  std::vector<std::string> out;
  for (const PointResult& r : results) out.push_back(r.id);
  return out;
}

TEST(Tune, ChoosesTheFastestPointUnderTheBudgetAtItCountingAsUnder) {
  const auto choice = tune(known_sweep(), "rel_rmse", 0.05);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->chosen.id, "c");
  EXPECT_EQ(choice->candidates, 2);  // c, d
  EXPECT_EQ(choice->points, 5);      // every ok point
  EXPECT_EQ(ids(choice->faster_over_budget), (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(choice->other_devices.empty());
  EXPECT_EQ(choice->metric, "rel_rmse");
  EXPECT_EQ(choice->max_error, 0.05);
}

TEST(Tune, JustUnderThePointsErrorTheNextFastestWins) {
  const auto choice = tune(known_sweep(), "rel_rmse", 0.0499);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->chosen.id, "d");
  EXPECT_EQ(ids(choice->faster_over_budget), (std::vector<std::string>{"a", "b", "c"}));
}

TEST(Tune, FailedPointsAreIgnored) {
  const auto choice = tune(known_sweep(), "rel_rmse", 1.0);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->chosen.id, "a");  // e is faster with no error, but failed
  EXPECT_TRUE(choice->faster_over_budget.empty());
}

TEST(Tune, NothingUnderTheBudgetIsNoChoice) {
  EXPECT_FALSE(tune(known_sweep(), "rel_rmse", 0.001));
  EXPECT_FALSE(tune({}, "rel_rmse", 1.0));
  EXPECT_FALSE(tune({point("e", 1, 0.0, {}, false)}, "rel_rmse", 1.0));
}

TEST(Tune, AnImageWithNaNOrInfIsOverAnyBudget) {
  std::vector<PointResult> results = known_sweep();
  PointResult nan_point = point("n", 1.5, 0.0);
  nan_point.metrics.nan_values = 3;
  results.push_back(nan_point);
  PointResult nan_figure = point("m", 1.6, NAN);
  results.push_back(nan_figure);
  const auto choice = tune(results, "rel_rmse", 0.05);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->chosen.id, "c");
  EXPECT_EQ(ids(choice->faster_over_budget), (std::vector<std::string>{"n", "m", "a", "b"}));
}

TEST(Tune, OnlyLowerIsBetterMetricsAreBudgets) {
  EXPECT_THROW(tune(known_sweep(), "psnr", 30), std::invalid_argument);
  EXPECT_THROW(tune(known_sweep(), "ssim", 0.9), std::invalid_argument);
  EXPECT_THROW(tune(known_sweep(), "rmes", 0.1), std::invalid_argument);
  EXPECT_THROW(tune(known_sweep(), "rel_rmse", NAN), std::invalid_argument);
  EXPECT_NO_THROW(tune(known_sweep(), "rmse", 0.1));
}

TEST(Tune, TunesOverTheFirstResultsDeviceAndNamesTheOthers) {
  std::vector<PointResult> results{point("x", 0.5, 0.0, {}, true, "NVIDIA H200"), point("y", 0.4, 0.0, {}, true, "AMD")};
  for (const PointResult& r : known_sweep()) results.push_back(r);
  results.insert(results.begin(), point("failed", 0.1, 0.0, {}, false, ""));
  const auto choice = tune(results, "rel_rmse", 0.05);
  ASSERT_TRUE(choice);
  EXPECT_EQ(choice->chosen.id, "x");  // the first ok result's device
  EXPECT_EQ(choice->points, 1);
  EXPECT_EQ(choice->other_devices, (std::vector<std::string>{"AMD", "llvmpipe (LLVM 15.0.6, 256 bits)"}));
}

SweepSpec demo_spec() {
  SweepSpec spec;
  spec.file = "configs/sweeps/fog.json";
  spec.config = std::string(::volgraph::testing::source_dir()) + "/configs/demo_fog.json";
  return spec;
}

TEST(TuneSummary, GivesTheFlagsThenTheFiguresAndTheFasterPointsThatLost) {
  const auto choice = tune(known_sweep(), "rel_rmse", 0.05);
  ASSERT_TRUE(choice);
  const std::string text = tuned_summary_text(demo_spec(), *choice, "rel_rmse", 0.05);
  EXPECT_EQ(text.rfind("--set sun_shadow.resolution=1024\n--variant fog_integral=hillaire\n--set fog_media.slices=32\nchosen: ", 0), 0u)
      << text;
  EXPECT_NE(text.find("4 ms median [3.9–4.1 ms] over 5 runs, rel_rmse 0.05 ≤ 0.05, on llvmpipe"), std::string::npos) << text;
  EXPECT_NE(text.find("2 of 5 points under the budget"), std::string::npos) << text;
  EXPECT_NE(text.find("faster, over the budget:\n  2 ms  rel_rmse 0.2 > 0.05  \"a\""), std::string::npos) << text;
  EXPECT_NE(text.find("  3 ms  rel_rmse 0.08 > 0.05  \"b\""), std::string::npos) << text;
  EXPECT_EQ(text.find("\"f\""), std::string::npos) << text;  // slower: not why c won
}

TEST(TuneSummary, QuotesForTheShellWhatNeedsIt) {
  TuneChoice choice;
  choice.chosen = point("p", 1, 0.01,
                        {{"fog_light", "\"hg\""}, {"fog_light.phase", "\"hg\""}, {"fog_light.flag", "\"true\""},
                         {"fog_light.tint", "[1,0.5,0.25]"}});
  const std::string text = tuned_summary_text(demo_spec(), choice, "rel_rmse", 0.05);
  EXPECT_EQ(text.rfind("--variant fog_light=hg\n--set fog_light.phase=hg\n--set 'fog_light.flag=\"true\"'\n"
                       "--set 'fog_light.tint=[1,0.5,0.25]'\n", 0),
            0u)
      << text;
}

TEST(TuneSummary, AFrameCountIsTheFramesFlag) {
  TuneChoice choice;
  choice.chosen = point("t", 1, 0.01, {{"fog_integral", "\"wronski\""}, {"frames", "8"}});
  const std::string text = tuned_summary_text(demo_spec(), choice, "rel_rmse", 0.05);
  EXPECT_EQ(text.rfind("--variant fog_integral=wronski\n--frames 8\n", 0), 0u) << text;
}

TEST(TuneSummary, APointOfAnotherGraphGivesGraphFlagAndNoOverlay) {
  TuneChoice choice;
  choice.chosen = point("g", 1, 0.01, {{"fog_march.steps", "64"}});
  choice.chosen.graph = "configs/graphs/raymarch_fog.json";
  EXPECT_FALSE(tuned_overlay_possible(choice));
  const std::string text = tuned_summary_text(demo_spec(), choice, "rel_rmse", 0.05);
  EXPECT_EQ(text.rfind("--graph configs/graphs/raymarch_fog.json\n--set fog_march.steps=64\n", 0), 0u) << text;
  EXPECT_NE(text.find("no overlay"), std::string::npos) << text;
  // Not an overlay: a document with the command, that the loader refuses rather than render the config's own graph.
  choice.metric = "rel_rmse";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("volgraph_tune_graph_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "tuned.json").string();
  const std::string doc = tuned_overlay_json(demo_spec(), choice, dir.string());
  std::ofstream(path) << doc;
  EXPECT_NE(doc.find("\"render_with\": \"volgraph render " + demo_spec().config +
                     " --graph configs/graphs/raymarch_fog.json --set fog_march.steps=64\""),
            std::string::npos)
      << doc;
  PassRegistry registry;
  register_builtin_passes(registry);
  try {
    load_config(path, registry);
    ADD_FAILURE() << "the document for a point of another graph loaded as a config";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/render_with"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

const PassNode* find_pass(const Config& config, const std::string& name) {
  for (const PassNode& p : config.passes) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

const ParamValue* find_param(const PassNode& pass, const std::string& name) {
  for (const ParamSetting& s : pass.params) {
    if (s.name == name) return &s.value;
  }
  return nullptr;
}

TEST(TuneOverlay, LoadsAsAConfigThatSetsThePointsVariantsAndParameters) {
  const auto choice = tune(known_sweep(), "rel_rmse", 0.05);
  ASSERT_TRUE(choice);
  ASSERT_TRUE(tuned_overlay_possible(*choice));
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("volgraph_tune_overlay_" + std::to_string(::getpid())) / "tuned";
  std::filesystem::create_directories(dir);
  const std::string text = tuned_overlay_json(demo_spec(), *choice, dir.string());
  const std::string path = (dir / "overlay.json").string();
  std::ofstream(path) << text;

  PassRegistry registry;
  register_builtin_passes(registry);
  const LoadedConfig loaded = load_config(path, registry);
  std::filesystem::remove_all(dir.parent_path());
  EXPECT_NE(text.find("\"include\": \""), std::string::npos);
  EXPECT_EQ(text.find("\"include\": \"/"), std::string::npos) << "relative to the overlay's folder: " << text;
  EXPECT_NE(loaded.config.description.find("tuned by volgraph tune: rel_rmse ≤ 0.05, rel_rmse 0.05, 4 ms median"),
            std::string::npos)
      << loaded.config.description;
  const PassNode* integral = find_pass(loaded.config, "fog_integral");
  const PassNode* media = find_pass(loaded.config, "fog_media");
  const PassNode* shadow = find_pass(loaded.config, "sun_shadow");
  ASSERT_TRUE(integral && media && shadow);
  EXPECT_EQ(integral->variant, "hillaire");
  ASSERT_TRUE(find_param(*media, "slices"));
  EXPECT_EQ(*find_param(*media, "slices"), ParamValue(int64_t{32}));
  ASSERT_TRUE(find_param(*shadow, "resolution"));
  EXPECT_EQ(*find_param(*shadow, "resolution"), ParamValue(int64_t{1024}));
  EXPECT_EQ(loaded.config.scene.objects.size(), 3u);  // the swept config's scene, included
}

TEST(TuneOverlay, TheWronskiPointSwitchesTheVariantTheConfigSetsOtherwiseAndNamesItsFrames) {
  TuneChoice choice;
  choice.chosen = point("w", 1, 0.01, {{"fog_integral", "\"wronski\""}, {"frames", "8"}});
  choice.metric = "rel_rmse";
  choice.max_error = 0.05;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("volgraph_tune_wronski_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "overlay.json").string();
  const std::string text = tuned_overlay_json(demo_spec(), choice, dir.string());
  EXPECT_NE(text.find("render it with --frames 8 (a config holds no frame count)"), std::string::npos) << text;
  std::ofstream(path) << text;
  PassRegistry registry;
  register_builtin_passes(registry);
  const LoadedConfig loaded = load_config(path, registry);
  std::filesystem::remove_all(dir);
  const PassNode* integral = find_pass(loaded.config, "fog_integral");
  ASSERT_TRUE(integral);
  EXPECT_EQ(integral->variant, "wronski");  // froxel_fog.json says hillaire
}

}  // namespace
}  // namespace volgraph::compare
