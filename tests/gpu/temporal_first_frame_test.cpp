// The first frame of a graph with temporal passes (froxel_temporal, pixel_temporal), on
// each backend: with no history yet, each temporal pass hands on this frame's values, so
// every shipped demo that accumulates over frames renders, on its first frame, the
// same image bit for bit as the same config with the temporal passes bypassed (their
// readers wired to the temporal pass's own inputs; the temporal pass is then unused and
// culled) — `render --frames 1` is what the graph without them renders.
#include <filesystem>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tests/gpu/shipped_configs.h"

namespace volgraph::testing {
namespace {

using ConfigOnBackend = std::tuple<std::string, Backend>;

// Per temporal pass type: its output slot → the input slot whose value it blends.
const std::map<std::string, std::map<std::string, std::string>>& temporal_slots() {
  static const std::map<std::string, std::map<std::string, std::string>> slots = {
      {"froxel_temporal", {{"accumulated", "in_scatter"}}},
      {"pixel_temporal", {{"scattering", "fog_scattering"}, {"transmittance", "fog_transmittance"}}}};
  return slots;
}

const PassNode* find_pass(const Config& config, const std::string& name) {
  for (const PassNode& p : config.passes) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

// "pass.slot" → what it would be with the temporal passes bypassed ("" when it is no
// temporal pass's output).
std::string bypassed_source(const Config& config, const std::string& source) {
  const size_t dot = source.find('.');
  const PassNode* pass = find_pass(config, source.substr(0, dot));
  if (!pass) return "";
  const auto type = temporal_slots().find(pass->type);
  if (type == temporal_slots().end()) return "";
  const auto input_slot = type->second.find(source.substr(dot + 1));
  if (input_slot == type->second.end()) return "";
  for (const InputWiring& w : pass->inputs) {
    if (w.slot == input_slot->second) return w.source;
  }
  return "";
}

// A config that includes `config` and amends every reader of a temporal pass's output to
// read that pass's input instead; "" when the config has no temporal pass.
std::string bypassing_config(const Config& config, const std::string& included_file) {
  std::ostringstream amendments;
  for (const PassNode& p : config.passes) {
    std::ostringstream inputs;
    for (const InputWiring& w : p.inputs) {
      const std::string source = bypassed_source(config, w.source);
      if (source.empty()) continue;
      inputs << (inputs.tellp() > 0 ? ", " : "") << '"' << w.slot << R"(": ")" << source << '"';
    }
    if (inputs.tellp() == 0) continue;
    amendments << (amendments.tellp() > 0 ? ",\n" : "") << R"({ "name": ")" << p.name << R"(", "inputs": { )" << inputs.str() << " } }";
  }
  if (amendments.tellp() == 0) return "";
  return R"({ "include": [")" + included_file + R"("], "graph": { "passes": [ )" + amendments.str() + " ] } }";
}

bool has_temporal_pass(const Config& config) {
  for (const PassNode& p : config.passes) {
    if (temporal_slots().contains(p.type)) return true;
  }
  return false;
}

// The shipped demos (configs/*.json) with a temporal pass; the oracle scenes under
// configs/tests/ use the same graph fragments.
std::vector<std::string> temporal_demos() {
  PassRegistry registry;
  register_builtin_passes(registry);
  std::vector<std::string> out;
  for (const std::string& c : shipped_configs()) {
    if (c.find('/') == std::string::npos && has_temporal_pass(load_config(config_path(c), registry).config)) out.push_back(c);
  }
  return out;
}

class TemporalFirstFrame : public OnEachBackend<ConfigOnBackend> {
 protected:
  Backend backend() const override { return std::get<1>(GetParam()); }
  const std::string& config() const { return std::get<0>(GetParam()); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  Texels first_frame(const LoadedConfig& c) {
    Executor executor(device(), c.graph, &c.config.scene, {});
    executor.run_frame();
    return executor.read_output(0);
  }
  PassRegistry registry_;
};

TEST_P(TemporalFirstFrame, IsBitIdenticalToTheGraphWithoutTemporalPasses) {
  Overrides o;
  o.size = kConfigTestSize;
  const std::filesystem::path path = config_path(config());
  const LoadedConfig with_temporal = load_config(path.string(), registry_, o);
  const std::string text = bypassing_config(with_temporal.config, path.filename().string());
  ASSERT_FALSE(text.empty()) << "a temporal pass nobody reads in " << config();
  const LoadedConfig without = load_config_text((path.parent_path() / "without_temporal.json").string(), text, registry_, o);
  for (const PassNode& p : without.config.passes) {
    for (const InputWiring& w : p.inputs) ASSERT_EQ(bypassed_source(without.config, w.source), "") << p.name << "." << w.slot;
  }
  const Texels a = first_frame(with_temporal), b = first_frame(without);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  for (size_t k = 0; k < a.rgba.size(); ++k) ASSERT_EQ(a.rgba[k], b.rgba[k]) << config() << " value " << k;
}

// pixel_temporal's own outputs on the first frame, at its default parameters, against
// the raymarch_fog outputs it blends (froxel_temporal's: TemporalFog.TheHistoryPair…):
// the rgb of the in-scattering and the transmittance, bit for bit, jitter on.
class PixelTemporalFirstFrame : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  PassRegistry registry_;
};

TEST_P(PixelTemporalFirstFrame, PassesThisFramesMarchThroughBitForBit) {
  const LoadedConfig c = load_config_text("pixel_temporal_first_frame.json", R"({ "output": { "size": [32, 24] },
  "scene": { "camera": { "position": [0, 1, 0], "target": [0, 1, -1], "fov_y_deg": 50, "near": 0.1, "far": 100 },
             "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
             "objects": [ { "shape": "box", "size": [1, 1.5, 1], "material": "grey", "transform": { "translate": [-0.5, 1, -4] } } ],
             "lights": [ { "type": "point", "position": [1.6, 2.2, -3.5], "intensity": [20, 20, 20] } ],
             "media": { "height_fog": { "sigma_s": [0.3, 0.3, 0.3], "sigma_a": [0.02, 0.02, 0.02], "base_height": 0, "falloff": 0.8 } } },
  "graph": { "passes": [
    { "name": "lit", "type": "scene" },
    { "name": "fog_march", "type": "raymarch_fog", "params": { "steps": 8, "max_distance": 12, "jitter": true }, "inputs": { "depth": "lit.depth" } },
    { "name": "fog_temporal", "type": "pixel_temporal",
      "inputs": { "depth": "lit.depth", "fog_scattering": "fog_march.fog_scattering", "fog_transmittance": "fog_march.fog_transmittance" } } ],
    "outputs": ["fog_temporal.scattering", "fog_temporal.transmittance", "fog_march.fog_scattering", "fog_march.fog_transmittance"] } })",
                                           registry_);
  Executor executor(device(), c.graph, &c.config.scene, {});
  executor.run_frame();
  for (uint32_t k = 0; k < 2; ++k) {
    const Texels blended = executor.read_output(k), marched = executor.read_output(k + 2);
    ASSERT_EQ(blended.rgba.size(), marched.rgba.size());
    size_t nonzero = 0;
    for (size_t i = 0; i < blended.rgba.size(); i += 4) {
      for (size_t ch = 0; ch < 3; ++ch) ASSERT_EQ(blended.rgba[i + ch], marched.rgba[i + ch]) << "output " << k << " texel " << i / 4;
      nonzero += marched.rgba[i] != 0;
    }
    EXPECT_GT(nonzero, blended.rgba.size() / 8) << "output " << k << ": the march has something to pass through";
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, PixelTemporalFirstFrame, ::testing::ValuesIn(gpu_backends()), backend_test_name);

std::string test_name(const ::testing::TestParamInfo<ConfigOnBackend>& info) {
  return config_test_name(std::get<0>(info.param)) + "_" + std::string(backend_name(std::get<1>(info.param)));
}

INSTANTIATE_TEST_SUITE_P(Shipped, TemporalFirstFrame,
                         ::testing::Combine(::testing::ValuesIn(temporal_demos()), ::testing::ValuesIn(gpu_backends())), test_name);

}  // namespace
}  // namespace volgraph::testing
