// Sweep specs: the expansion of series into points (order, counts, ranges), stable and
// unique ids, and one diagnostic (file, JSON pointer, line, expectation) for each
// broken spec of tests/compare/specs/, a point the config refuses included.
#include "tools/compare/sweep_spec.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "passes/passes.h"
#include "tests/support/source_dir.h"

namespace volgraph::compare {
namespace {

using Settings = std::vector<std::pair<std::string, std::string>>;

std::string spec_file(const std::string& name) { return std::string(::volgraph::testing::source_dir()) + "/tests/compare/specs/" + name; }
std::string demo_fog() { return std::string(::volgraph::testing::source_dir()) + "/configs/demo_fog.json"; }

class SweepSpecTest : public ::testing::Test {
 protected:
  SweepSpecTest() { register_builtin_passes(registry_); }

  SweepSpec read(const std::string& name) { return read_sweep_spec(spec_file(name), registry_); }

  // A spec of demo_fog with one series varying `key` over `values` (JSON text), written to a temporary folder.
  SweepSpec read_vary(const std::string& key, const std::string& values) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("volgraph_sweep_spec_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "vary.json").string();
    std::ofstream(path) << "{ \"config\": \"" << demo_fog() << "\", \"size\": [64, 36],\n"
                        << "  \"series\": [ { \"name\": \"s\", \"vary\": { \"" << key << "\": " << values << " } } ] }\n";
    SweepSpec spec = read_sweep_spec(path, registry_);
    std::filesystem::remove_all(dir);
    return spec;
  }

  // The JSON texts a varied key takes, point by point.
  std::vector<std::string> values_of(const std::string& key, const std::string& values) {
    std::vector<std::string> out;
    for (const SweepPoint& p : read_vary(key, values).points) out.push_back(p.settings.back().second);
    return out;
  }

  PassRegistry registry_;
};

TEST_F(SweepSpecTest, ReadsTheSettingsOfTheSpec) {
  const SweepSpec spec = read("good.json");
  EXPECT_EQ(spec.file, spec_file("good.json"));
  EXPECT_EQ(spec.description, "Test: the froxel chain's integration and slices, the ray march's steps, the config as it is.");
  EXPECT_TRUE(std::filesystem::equivalent(spec.config, demo_fog()));
  EXPECT_EQ(spec.size, (Extent{64, 36, 1}));
  EXPECT_EQ(spec.runs, 3);
  EXPECT_EQ(spec.warmup, 0);
  EXPECT_EQ(spec.frames, 2);
  EXPECT_EQ(spec.backend, "vulkan");
  EXPECT_EQ(spec.reference, "cpu");
  EXPECT_EQ(spec.reference_mode, "straight");  // the default
  EXPECT_EQ(spec.metric, "rel_rmse");
  EXPECT_EQ(spec.mask, "fog_only");
}

TEST_F(SweepSpecTest, AReferenceImageIsResolvedFromTheSpecsFolder) {
  const SweepSpec spec = read("good_reference.json");
  EXPECT_EQ(spec.reference, spec_file("reference.PFM"));
  EXPECT_EQ(spec.metric, "rel_rmse");  // the defaults
  EXPECT_EQ(spec.mask, "all");
  EXPECT_EQ(spec.frames, 1);
  EXPECT_EQ(spec.backend, "vulkan");
  ASSERT_EQ(spec.points.size(), 1u);
  EXPECT_EQ(spec.points[0].label, "froxel");
}

TEST_F(SweepSpecTest, ExpandsTheCartesianProductWithTheLastKeyFastest) {
  const SweepSpec spec = read("good.json");
  ASSERT_EQ(spec.points.size(), 6u + 3u + 1u);  // 2 × 3 froxel, 3 ray-march steps, 1 default
  const std::vector<std::string> labels{
      "fog_integral=wronski, fog_media.slices=16",  "fog_integral=wronski, fog_media.slices=32",
      "fog_integral=wronski, fog_media.slices=64",  "fog_integral=hillaire, fog_media.slices=16",
      "fog_integral=hillaire, fog_media.slices=32", "fog_integral=hillaire, fog_media.slices=64",
  };
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_EQ(spec.points[i].label, labels[i]) << i;
    EXPECT_EQ(spec.points[i].series, "froxel");
    EXPECT_EQ(spec.points[i].graph, "");
  }
  const SweepPoint& p = spec.points[4];
  EXPECT_EQ(p.settings, (Settings{{"sun_shadow.resolution", "1024"}, {"fog_integral", "\"hillaire\""}, {"fog_media.slices", "32"}}));
  EXPECT_EQ(p.overrides.sets, (std::vector<std::string>{"sun_shadow.resolution=1024", "fog_media.slices=32"}));
  EXPECT_EQ(p.overrides.variants, (std::vector<std::string>{"fog_integral=hillaire"}));
  EXPECT_EQ(p.overrides.graph, "");
  EXPECT_FALSE(p.overrides.size);
}

TEST_F(SweepSpecTest, ASeriesGraphIsResolvedAndASeriesWithoutVaryIsOnePointNamedAfterIt) {
  const SweepSpec spec = read("good.json");
  ASSERT_EQ(spec.points.size(), 10u);
  for (size_t i = 6; i < 9; ++i) {
    EXPECT_EQ(spec.points[i].series, "raymarch");
    EXPECT_TRUE(std::filesystem::equivalent(spec.points[i].graph, std::string(::volgraph::testing::source_dir()) + "/configs/graphs/raymarch_fog.json"));
    EXPECT_EQ(spec.points[i].overrides.graph, spec.points[i].graph);
  }
  EXPECT_EQ(spec.points[6].label, "fog_march.steps=16");
  EXPECT_EQ(spec.points[8].label, "fog_march.steps=64");
  const SweepPoint& d = spec.points[9];
  EXPECT_EQ(d.label, "default");
  EXPECT_TRUE(d.settings.empty());
  EXPECT_TRUE(d.overrides.sets.empty() && d.overrides.variants.empty() && d.overrides.graph.empty());
}

TEST_F(SweepSpecTest, FramesSetThePointsFrameCountNotThePasses) {
  const SweepSpec spec = read("good_frames.json");
  ASSERT_EQ(spec.points.size(), 4u + 1u);
  const std::vector<int> frames{1, 2, 4, 8, 3};  // the ranged counts, then the spec's
  for (size_t i = 0; i < frames.size(); ++i) EXPECT_EQ(spec.points[i].frames, frames[i]) << i;
  EXPECT_EQ(spec.points[2].label, "frames=4");
  EXPECT_EQ(spec.points[2].settings, (Settings{{"fog_integral", "\"wronski\""}, {"frames", "4"}}));
  EXPECT_EQ(spec.points[2].overrides.variants, (std::vector<std::string>{"fog_integral=wronski"}));
  EXPECT_TRUE(spec.points[2].overrides.sets.empty());
}

// Every spec shipped in configs/sweeps/ reads (and each of its points loads against its config).
TEST_F(SweepSpecTest, EveryShippedSpecReads) {
  const std::filesystem::path dir = std::filesystem::path(::volgraph::testing::source_dir()) / "configs" / "sweeps";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no configs/sweeps";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    try {
      EXPECT_FALSE(read_sweep_spec(entry.path().string(), registry_).points.empty()) << entry.path();
    } catch (const ConfigError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

TEST_F(SweepSpecTest, GeometricRangesMultiplyUpToTheEnd) {
  EXPECT_EQ(values_of("fog_media.slices", R"({"from": 16, "to": 128, "times": 2})"),
            (std::vector<std::string>{"16", "32", "64", "128"}));
  EXPECT_EQ(values_of("fog_media.slices", R"({"from": 16, "to": 100, "times": 2})"),
            (std::vector<std::string>{"16", "32", "64"}));
  EXPECT_EQ(values_of("fog_media.slices", R"({"from": 5, "to": 5, "times": 3})"), (std::vector<std::string>{"5"}));
  // Not integers (times 1.5): doubles, each exact in binary here.
  EXPECT_EQ(values_of("fog_media.far", R"({"from": 1, "to": 10, "times": 1.5})"),
            (std::vector<std::string>{"1.0", "1.5", "2.25", "3.375", "5.0625", "7.59375"}));
}

TEST_F(SweepSpecTest, ArithmeticRangesIncludeTheEnd) {
  EXPECT_EQ(values_of("fog_media.far", R"({"from": 20, "to": 60, "step": 20})"), (std::vector<std::string>{"20", "40", "60"}));
  EXPECT_EQ(values_of("fog_media.far", R"({"from": 1, "to": 2.9, "step": 1})"), (std::vector<std::string>{"1", "2"}));
  // 0.1 + 2 × 0.1 is 0.30000000000000004 in doubles: rounded to 12 digits, the end included.
  EXPECT_EQ(values_of("fog_media.near", R"({"from": 0.1, "to": 0.3, "step": 0.1})"),
            (std::vector<std::string>{"0.1", "0.2", "0.3"}));
  // (0.3 − 0)/0.1 is 2.9999999999999996: within 1e-9 of 3 steps, so 0.3 is in.
  EXPECT_EQ(values_of("sun_shadow.pcf_radius", R"({"from": 0, "to": 0.3, "step": 0.1})"),
            (std::vector<std::string>{"0.0", "0.1", "0.2", "0.3"}));
  EXPECT_EQ(values_of("sun_shadow.pcf_radius", R"({"from": 0, "to": 0.5, "step": 0.1})"),  // 3 × 0.1 is 0.30000000000000004
            (std::vector<std::string>{"0.0", "0.1", "0.2", "0.3", "0.4", "0.5"}));
  EXPECT_EQ(values_of("sun_shadow.pcf_radius", R"({"from": 0, "to": 1, "step": 0.25})"),
            (std::vector<std::string>{"0.0", "0.25", "0.5", "0.75", "1.0"}));
}

// FNV-1a 64 written out again here, apart from the reader's.
std::string fnv1a_48_hex(const std::string& bytes) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  char buf[16];
  std::snprintf(buf, sizeof buf, "%012llx", static_cast<unsigned long long>(h & 0xffffffffffffull));
  return buf;
}

TEST_F(SweepSpecTest, IdsAreTheDocumentedHashOfSeriesGraphAndSettings) {
  const SweepSpec spec = read("good.json");
  const SweepPoint& p = spec.points[0];
  const std::string bytes = "froxel\n\nsun_shadow.resolution=1024\nfog_integral=\"wronski\"\nfog_media.slices=16\n";
  EXPECT_EQ(fnv1a_48_hex(bytes), "348d056109ff");  // the same bytes hashed by Python, once
  EXPECT_EQ(p.id, "348d056109ff");
  EXPECT_EQ(spec.points[9].id, fnv1a_48_hex("default\n\n"));
  EXPECT_EQ(spec.points[6].id, fnv1a_48_hex("raymarch\n../../../configs/graphs/raymarch_fog.json\nfog_march.steps=16\n"));
}

TEST_F(SweepSpecTest, IdsAreUniqueAndTheSameOnEveryRead) {
  const SweepSpec a = read("good.json"), b = read("good.json");
  std::set<std::string> ids;
  ASSERT_EQ(a.points.size(), b.points.size());
  for (size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].id, b.points[i].id);
    EXPECT_EQ(a.points[i].id.size(), 12u);
    EXPECT_EQ(a.points[i].id.find_first_not_of("0123456789abcdef"), std::string::npos);
    ids.insert(a.points[i].id);
  }
  EXPECT_EQ(ids.size(), a.points.size());
}

struct BrokenSpec {
  const char* file;
  const char* pointer;
  const char* expected;  // a part of the one message
};

class BrokenSpecTest : public SweepSpecTest, public ::testing::WithParamInterface<BrokenSpec> {};

TEST_P(BrokenSpecTest, GivesOneMessageWithFilePointerAndExpectation) {
  const BrokenSpec& c = GetParam();
  const std::string path = spec_file(c.file);
  try {
    read_sweep_spec(path, registry_);
    FAIL() << c.file << " was accepted";
  } catch (const ConfigError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    const Diagnostic& d = e.diagnostics()[0];
    EXPECT_EQ(d.where.file, path);
    EXPECT_EQ(d.where.pointer, c.pointer) << e.what();
    EXPECT_GT(d.where.line, 0) << e.what();
    EXPECT_NE(d.message.find(c.expected), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

const BrokenSpec kBrokenSpecs[] = {
    {"bad_unknown_key.json", "/runz", "unknown key \"runz\" (did you mean \"runs\"?)"},
    {"bad_size_range.json", "/size/0", "expected an integer in [1, 16384], got 0"},
    {"bad_size_shape.json", "/size", "expected [width, height] in pixels, got an array of 1"},
    {"bad_runs.json", "/runs", "expected an integer in [1, 1000], got 1001"},
    {"bad_warmup.json", "/warmup", "expected an integer in [0, 100], got -1"},
    {"bad_frames.json", "/frames", "expected an integer in [1, 1000], got 0"},
    {"bad_backend.json", "/backend", "unknown backend \"vulkn\" (did you mean \"vulkan\"?); expected one of vulkan, webgpu"},
    {"bad_reference_ext.json", "/reference", "expected \"cpu\" (the CPU reference renderer) or a linear image file (.pfm or .exr)"},
    {"bad_reference_missing.json", "/reference", "file not found: \"missing.pfm\""},
    {"bad_metric.json", "/metric", "unknown metric \"rmes\" (did you mean \"rmse\"?); expected one of rmse, rel_rmse"},
    {"bad_mask.json", "/mask", "unknown mask \"fog\"; expected one of all, fog_only, surfaces"},
    {"bad_reference_mode.json", "/reference_mode", "unknown reference_mode \"refrac\"; expected one of straight, refracted"},
    {"bad_config_missing.json", "/config", "file not found: \"no_such_config.json\""},
    {"bad_config_broken.json", "/config", "the config does not load: " },
    {"bad_no_config.json", "/", "missing \"config\""},
    {"bad_no_series.json", "/", "missing \"series\""},
    {"bad_series_empty.json", "/series", "expected a non-empty array of series"},
    {"bad_series_name_taken.json", "/series/1/name", "series name \"a\" is taken by /series/0; expected a unique name"},
    {"bad_series_no_name.json", "/series/0", "missing \"name\""},
    {"bad_series_unknown_key.json", "/series/0/vray", "unknown key \"vray\" (did you mean \"vary\"?)"},
    {"bad_graph_missing.json", "/series/0/graph", "file not found: \"no_such_graph.json\""},
    {"bad_key.json", "/series/0/set/fog media", "expected a key \"PASS\" (picks a variant), \"PASS.PARAM\" (sets a parameter) or \"frames\""},
    {"bad_variant_value.json", "/series/0/set/fog_integral", "expected the name of a variant of pass \"fog_integral\""},
    {"bad_param_value.json", "/series/0/set/fog_media.slices", "expected a value for parameter \"fog_media.slices\""},
    {"bad_vary_empty.json", "/series/0/vary/fog_media.slices", "expected a non-empty array of values, or a range"},
    {"bad_vary_duplicate.json", "/series/0/vary/fog_media.slices/2", "the value 16 is listed twice"},
    {"bad_set_and_vary.json", "/series/0/vary/fog_media.slices", "is in \"set\" too (/series/0/set/fog_media.slices)"},
    {"bad_range_both.json", "/series/0/vary/fog_media.slices", "expected a range {\"from\", \"to\", \"times\"} (geometric)"},
    {"bad_range_to.json", "/series/0/vary/fog_media.slices/to", "expected \"to\" a number ≥ \"from\" (64), got the number 16"},
    {"bad_range_times.json", "/series/0/vary/fog_media.slices/times", "expected \"times\" a number > 1"},
    {"bad_range_variant.json", "/series/0/vary/fog_integral", "a range needs a parameter key \"PASS.PARAM\""},
    {"bad_range_huge.json", "/series/0/vary/fog_media.far", "the range expands to 1000000001 values; expected at most 10000"},
    {"bad_too_many_points.json", "/series/0", "series \"a\" expands to 200 × 100 points, more than 10000"},
    {"bad_frames_value.json", "/series/0/vary/frames/1", "expected an integer in [1, 1000], got 0"},
    {"bad_frames_range.json", "/series/0/vary/frames", "expected a range of frame counts, integers in [1, 1000]"},
    // 40.0 is 40 and the order of the keys does not matter: slices 32 is rendered by both series.
    {"bad_repeated_point.json", "/series/1",
     "series \"fine\"'s point \"fog_media.far=40.0, fog_media.slices=32, fog_integral=wronski\" renders what series \"coarse\"'s "
     "point \"fog_media.slices=32\" does"},
    {"bad_json.json", "", "invalid JSON"},
    {"bad_duplicate_key.json", "/runs", "duplicate key \"runs\" (first at line 3)"},
    // What the config refuses, at the series' key, with the loader's message (once for the two points that make it).
    {"bad_refused_param.json", "/series/0/vary/fog_media.slices/1",
     "the config refuses series \"froxel\"'s point \"fog_media.slices=1000, fog_integral=wronski\": --set fog_media.slices=1000"},
    // A key the config refuses at every value: one message at the key.
    {"bad_refused_unknown_param.json", "/series/0/vary/fog_media.slicez",
     "the config refuses series \"froxel\"'s \"fog_media.slicez\" at the values 16, 32: --set fog_media.slicez=16: pass type "
     "\"froxel_voxelize\" has no parameter \"slicez\" (did you mean \"slices\"?)"},
    {"bad_refused_range.json", "/series/0/vary/fog_media.slices", "point \"fog_media.slices=1024\": --set fog_media.slices=1024"},
    {"bad_refused_pass.json", "/series/0/set/fog_nothing.slices", "no pass named \"fog_nothing\""},
    {"bad_refused_variant.json", "/series/0/vary/fog_integral/1", "--variant fog_integral=hilaire"},
    {"bad_refused_graph_point.json", "/series/1/set/fog_media.slices", "the config refuses series \"raymarch\"'s point \"raymarch\""},
    {"bad_refused_near_far.json", "/series/0", "must exceed near"},
};

INSTANTIATE_TEST_SUITE_P(Fixtures, BrokenSpecTest, ::testing::ValuesIn(kBrokenSpecs), [](const auto& info) {
  std::string name = info.param.file;
  name = name.substr(0, name.find('.'));
  return name;
});

TEST_F(SweepSpecTest, AnUnreadableSpecIsOneMessageAtTheFile) {
  const std::string path = spec_file("no_such_spec.json");
  try {
    read_sweep_spec(path, registry_);
    FAIL() << "accepted";
  } catch (const ConfigError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    EXPECT_EQ(e.diagnostics()[0].where.file, path);
    EXPECT_NE(e.diagnostics()[0].message.find("no such file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace volgraph::compare
