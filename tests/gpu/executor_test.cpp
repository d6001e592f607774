// The executor runs a compiled plan through the backend interface, on each backend:
// exact values for a graph whose answer is known, the same image under every debug
// switch, tone maps equal to the CPU twin, GPU times per pass, validation silent.
#include <string>
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "graph/rhi/device_error.h"
#include "passes/passes.h"
#include "physics/camera.h"
#include "physics/lighting.h"
#include "physics/srgb.h"
#include "physics/tonemap.h"
#include "tests/gpu/backends.h"
#include "tests/support/source_dir.h"

namespace volgraph::testing {
namespace {

class ExecutorTest : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  LoadedConfig load(const Overrides& o = {}) {
    return load_config(std::string(::volgraph::testing::source_dir()) + "/configs/tests/clear_composite.json", registry_, o);
  }
  Texels render(const LoadedConfig& c, const CompileOptions& options, int frames = 1) {
    Executor executor(device(), c.graph, &c.config.scene, options);
    for (int f = 0; f < frames; ++f) executor.run_frame();
    last_timings_ = executor.timings();
    return executor.read_output(0);
  }

  PassRegistry registry_;
  std::vector<PassTiming> last_timings_;
};

TEST_P(ExecutorTest, ClearedRadianceComesOutExactly) {
  const Texels t = render(load(), {});
  ASSERT_EQ(t.width, 40u);
  ASSERT_EQ(t.height, 24u);
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    ASSERT_EQ(t.rgba[i + 0], 0.5f) << i;
    ASSERT_EQ(t.rgba[i + 1], 0.25f) << i;
    ASSERT_EQ(t.rgba[i + 2], 2.0f) << i;
    ASSERT_EQ(t.rgba[i + 3], 1.0f) << i;
  }
  ASSERT_EQ(last_timings_.size(), 3u);  // unused_branch is culled
  for (const PassTiming& p : last_timings_) {
    if (device().has_timestamps()) EXPECT_GT(p.gpu_ms, 0.0) << p.pass;
    EXPECT_GE(p.cpu_ms, 0.0) << p.pass;
  }
}

TEST_P(ExecutorTest, DebugSwitchesGiveTheSameImage) {
  const LoadedConfig c = load();
  const Texels reference = render(c, {});
  for (const CompileOptions& o : {CompileOptions{.cull = false}, CompileOptions{.alias = false}, CompileOptions{.serialize = true}}) {
    EXPECT_EQ(render(c, o).rgba, reference.rgba) << "cull " << o.cull << " alias " << o.alias << " serialize " << o.serialize;
  }
}

TEST_P(ExecutorTest, ToneMapsMatchTheCpuTwinOverSeveralFrames) {
  for (const char* variant : {"aces", "reinhard"}) {
    Overrides o;
    o.variants = {std::string("out=") + variant};
    o.sets = {"out.exposure=0.5"};
    const Texels t = render(load(o), {}, 3);
    const physics::Rgb want = physics::tone_map({0.5, 0.25, 2.0}, 0.5,
                                                std::string(variant) == "aces" ? physics::ToneMap::aces : physics::ToneMap::reinhard);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(t.rgba[size_t(ch)], want[size_t(ch)], 1e-5 * want[size_t(ch)]) << variant;
  }
}

// The value a rgba16_float target holds for a float that rounds to 0.5 (which half holds
// exactly): 0.5 itself, or one half step below it where the driver rounds toward zero, as
// Vulkan allows for conversions to 16-bit floats (NVIDIA's 580 driver writes 0.499756 for
// ρE/π computed a float rounding below 0.5; lavapipe rounds to nearest).
void expect_half_of(float value, const std::string& where) {
  EXPECT_TRUE(value == 0.5f || value == 0.5f - 0x1p-12f) << where << ": " << value;
}

// DESIGN.md: a Lambertian plane of albedo ρ facing a directional light of irradiance E
// renders ρE/π: 0.5 · π / π = 0.5, which the rgba16_float target holds exactly.
TEST_P(ExecutorTest, LambertPlaneRendersRhoEOverPi) {
  const LoadedConfig c = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/tests/lambert_plane_lit.json", registry_);
  const Texels t = render(c, {});
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    for (size_t ch = 0; ch < 3; ++ch) expect_half_of(t.rgba[i + ch], "texel " + std::to_string(i / 4));
  }
}

// A Lambertian plane whose ρE/π no fp16 value holds (ρ 0.8, 0.3, 0.7 under E 1, 2.5, 0.9):
// the default rgba16_float colour holds it within one fp16 step (Vulkan lets the conversion
// round toward zero: lavapipe truncates), and with the colour overridden to rgba32_float
// the plane renders ρE/π to float precision (2 ulp relative).
std::string inexact_lambert_plane(const std::string& color_format) {
  return R"({
    "output": { "size": [16, 12] },
    "scene": {
      "camera": { "position": [0, 3, 0.001], "target": [0, 0, 0], "fov_y_deg": 30 },
      "materials": { "m": { "albedo": [0.8, 0.3, 0.7] } },
      "objects": [ { "shape": "plane", "size": [100, 1, 100], "material": "m" } ],
      "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": [1, 2.5, 0.9] } ] },
    "graph": { "passes": [
      { "name": "lit", "type": "scene")" +
         (color_format.empty() ? std::string() : R"(, "outputs": { "color": { "format": ")" + color_format + R"(" } })") + R"( },
      { "name": "out", "type": "composite", "variant": "none", "inputs": { "color": "lit.color" } } ],
      "outputs": ["out.output"] } })";
}

double fp16_step_at(double v) { return std::ldexp(1.0, std::ilogb(v) - 10); }

// The largest error of any texel's channel against ρE/π, relative to `scale(ρE/π)`.
template <typename Scale>
double worst_lambert_error(const Texels& t, Scale scale) {
  const double want[3] = {0.8 / M_PI, 0.75 / M_PI, 0.63 / M_PI};
  double worst = 0;
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    for (size_t ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(t.rgba[i + ch] - want[ch]) / scale(want[ch]));
  }
  return worst;
}

TEST_P(ExecutorTest, LambertPlaneIsWithinOneFp16StepOfRhoEOverPi) {
  const Texels t = render(load_config_text("lambert.json", inexact_lambert_plane(""), registry_), {});
  EXPECT_LT(worst_lambert_error(t, fp16_step_at), 1.0);
}

TEST_P(ExecutorTest, LambertPlaneInRgba32fIsRhoEOverPiToFloatPrecision) {
  const Texels t = render(load_config_text("lambert.json", inexact_lambert_plane("rgba32_float"), registry_), {});
  EXPECT_LE(worst_lambert_error(t, [](double v) { return v; }), 2.4e-7);
}

// The point-light demo, linear, against the CPU twin: for pixels that see the ground
// plane, ρ/π · I/d² · cos θ within 2e-3 relative (fp16 radiance target: 1e-3).
TEST_P(ExecutorTest, PointLightRadianceMatchesTheCpuTwin) {
  Overrides o;
  o.variants = {"final=none"};
  o.size = Extent{64, 36, 1};
  const LoadedConfig c = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/demo_point_lights.json", registry_, o);
  for (const CompileOptions& options : {CompileOptions{}, CompileOptions{.alias = false}, CompileOptions{.serialize = true}}) {
    const Texels t = render(c, options);
    const Scene& scene = c.config.scene;
    const Material* ground = scene.find_material("white");
    ASSERT_NE(ground, nullptr);
    int checked = 0;
    for (uint32_t j = t.height / 2 + 4; j < t.height; j += 3) {
      for (uint32_t i = 0; i < t.width; i += 5) {
        const Vec3 d = physics::pixel_ray(scene.camera, t.width, t.height, i, j);
        if (d[1] >= 0) continue;
        const double s = -scene.camera.position[1] / d[1];
        const Vec3 p{scene.camera.position[0] + s * d[0], 0.0, scene.camera.position[2] + s * d[2]};
        if (std::abs(p[0]) > 5 || std::abs(p[2]) > 5) continue;  // off the 10 m plane
        const Vec3 want = physics::lambert(ground->albedo, physics::irradiance(scene.lights[0], p, {0, 1, 0}));
        for (size_t ch = 0; ch < 3; ++ch) {
          EXPECT_NEAR(t.rgba[4 * (j * t.width + i) + ch], want[ch], 2e-3 * want[ch]) << i << ", " << j;
        }
        ++checked;
      }
    }
    EXPECT_GT(checked, 20);
  }
}

// A textured plane: albedo = factor × the texture's sRGB-decoded value, with the image's
// top row toward −z (passes/plumbing/meshes.h). Texels away from the halves' border and the
// plane's edges, within the fp16 target's 2e-3 relative plus a quarter of the sRGB code
// step (Vulkan lets the sRGB decode approximate; lavapipe's is off by 0.14 steps at 64).
TEST_P(ExecutorTest, AlbedoTextureMultipliesTheFactorInLinearLight) {
  const LoadedConfig c = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/tests/textured_plane.json", registry_);
  const Texels t = render(c, {});
  const Camera& camera = c.config.scene.camera;
  auto linear = [](int code) { return double(physics::srgb_decode(float(code) / 255)); };
  auto code_step = [&](int code) { return linear(std::min(code + 1, 255)) - linear(std::max(code - 1, 0)); };
  const int grey_code[3] = {188, 188, 188}, orange_code[3] = {255, 64, 0};
  int top = 0, bottom = 0;
  for (uint32_t j = 0; j < t.height; ++j) {
    for (uint32_t i = 0; i < t.width; ++i) {
      const Vec3 d = physics::pixel_ray(camera, t.width, t.height, i, j);
      const double s = -camera.position[1] / d[1];
      const double x = camera.position[0] + s * d[0], z = camera.position[2] + s * d[2];
      if (std::abs(x) > 0.4 || std::abs(z) > 0.4 || std::abs(z) < 0.1) continue;
      const int* code = z < 0 ? grey_code : orange_code;
      (z < 0 ? top : bottom)++;
      for (size_t ch = 0; ch < 3; ++ch) {
        const double want = 0.5 * linear(code[ch]), tolerance = 2e-3 * want + 0.5 * 0.25 * code_step(code[ch]) / 2;
        EXPECT_NEAR(t.rgba[4 * (j * t.width + i) + ch], want, tolerance) << i << ", " << j << " ch " << ch;
      }
    }
  }
  EXPECT_GT(top, 50);
  EXPECT_GT(bottom, 50);
}

// The same plane with its shadow map wired: nothing occludes it, so still exactly ρE/π
// (the depth bias keeps the plane from shadowing itself).
TEST_P(ExecutorTest, ShadowMappedPlaneDoesNotShadowItself) {
  const LoadedConfig c = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/tests/lambert_plane.json", registry_);
  const Texels t = render(c, {});
  for (size_t i = 0; i < t.rgba.size(); i += 4) {
    for (size_t ch = 0; ch < 3; ++ch) expect_half_of(t.rgba[i + ch], "texel " + std::to_string(i / 4) + " ch " + std::to_string(ch));
  }
}

// DESIGN.md: a surface in full shadow renders only what other terms give it — here the
// ambient irradiance A: ρA/π under the slab, ρ(E + A)/π in the open (fp16: 2e-3 relative).
TEST_P(ExecutorTest, FullShadowLeavesOnlyTheOtherTerms) {
  const LoadedConfig c = load_config(std::string(::volgraph::testing::source_dir()) + "/configs/tests/full_shadow.json", registry_);
  const Texels t = render(c, {});
  const Scene& scene = c.config.scene;
  const double shadowed = 0.5 * 0.4 / M_PI, open = 0.5 * (M_PI + 0.4) / M_PI;
  int in_shadow = 0, in_light = 0;
  for (uint32_t j = 0; j < t.height; ++j) {
    for (uint32_t i = 0; i < t.width; ++i) {
      const Vec3 d = physics::pixel_ray(scene.camera, t.width, t.height, i, j);
      if (d[1] >= 0) continue;
      const double s = -scene.camera.position[1] / d[1];
      const double x = scene.camera.position[0] + s * d[0], z = scene.camera.position[2] + s * d[2];
      const bool under = std::abs(x) < 0.8 && std::abs(z) < 0.8;        // well inside the slab's shadow
      const bool clear = std::abs(x) > 1.2 || std::abs(z) > 1.2;        // well outside it
      if ((!under && !clear) || std::abs(x) > 14 || std::abs(z) > 14) continue;  // on the 30 m plane
      const float got = t.rgba[4 * (j * t.width + i)];
      EXPECT_NEAR(got, under ? shadowed : open, 2e-3 * (under ? shadowed : open)) << i << ", " << j;
      (under ? in_shadow : in_light) += 1;
    }
  }
  EXPECT_GT(in_shadow, 20);
  EXPECT_GT(in_light, 20);
}

TEST_P(ExecutorTest, APassTypeWithoutAnImplementationIsNamed) {
  PassDecl future;
  future.name = "future_technique";
  future.kind = PassKind::compute;
  future.variants = {{"default", ""}};
  future.slots = {slot_inout("color", ResourceKind::texture2d, Usage::storage_read_write, "")};
  registry_.add(future);
  const std::string text = R"({
    "output": { "size": [8, 8] },
    "graph": { "passes": [
      { "name": "c", "type": "clear" },
      { "name": "f", "type": "future_technique", "inputs": { "color": "c.target" } }
    ], "outputs": ["f.color"] } })";
  const LoadedConfig c = load_config_text("test.json", text, registry_);
  try {
    Executor executor(device(), c.graph, &c.config.scene, {});
    FAIL() << "expected a DeviceError";
  } catch (const DeviceError& e) {
    EXPECT_EQ(e.kind, DeviceError::Kind::unsupported);
    EXPECT_NE(std::string(e.what()).find("pass \"f\" (future_technique) has no GPU implementation yet"), std::string::npos)
        << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, ExecutorTest, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
