// The weather map (scene.clouds.weather_map → cloud_weather_map → cloud_march's and
// cloud_shadow_map's `weather`) on both backends: an all-white map (r = 1, g = the layer's
// type) draws what no map draws, within fp16 rounding; an all-black r draws no cloud (T = 1
// exactly, τ = 0 exactly); a map black over one half and white over the other draws clouds
// only over the white half; the texture holds the image's bytes. docs/clouds.md "Weather map".
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/config/config.h"
#include "graph/execute/executor.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"
#include "tools/image_io.h"

namespace volgraph::testing {
namespace {

constexpr int kMapSide = 16;
constexpr uint8_t kLayerType = 153;  // the layer's type 0.6 = 153 / 255 exactly: a map's g can equal it

// A 16 × 16 RGB(A) PNG whose texel (x, y) is `texel(x, y)`, written under the test's temp folder.
template <typename Texel>
std::string write_map(const std::string& name, Texel texel) {
  std::vector<uint8_t> rgba;
  for (int y = 0; y < kMapSide; ++y)
    for (int x = 0; x < kMapSide; ++x) {
      const std::array<uint8_t, 2> rg = texel(x, y);
      rgba.insert(rgba.end(), {rg[0], rg[1], 0, 255});
    }
  const std::vector<std::byte> png = encode_png_rgba8(kMapSide, kMapSide, rgba);
  const std::string path = (std::filesystem::path(::testing::TempDir()) / ("cloud_weather_" + name + ".png")).string();
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  return path;
}

// A 24 × 24 frame looking up 73° from 2 m at x = `camera_x` (its rays enter the layer within
// ±2 km of it in x); the layer without wind, `map` its weather map over 16 km (none: ""); outputs
// the march's clouds (a the transmittance) and the shadow map's τ.
std::string weather_config_text(const std::string& map, double camera_x) {
  const std::string x = std::to_string(camera_x);
  const std::string weather_map = map.empty() ? "" : R"(, "weather_map": { "image": ")" + map + R"(", "size": 16000 })";
  const std::string weather_pass = map.empty() ? "" : R"({ "name": "weather", "type": "cloud_weather_map", "params": { "size": 16 } },)";
  const std::string weather_input = map.empty() ? "" : R"(, "weather": "weather.weather")";
  return R"({ "output": { "size": [24, 24] },
  "scene": { "camera": { "position": [)" + x + R"(, 2, 0], "target": [)" + x + R"(, 3, -0.3], "fov_y_deg": 50 },
    "materials": { "grey": { "albedo": [0.5, 0.5, 0.5] } },
    "objects": [ { "name": "box", "shape": "box", "material": "grey", "size": [1, 1, 1], "transform": { "translate": [0, 0, 6000] } } ],
    "lights": [ { "name": "sun", "type": "directional", "direction": [0.3, -0.8, -0.5], "irradiance": [3, 3, 3] } ],
    "clouds": { "coverage": 0.8, "type": 0.6, "wind": [0, 0, 0])" + weather_map + R"( } },
  "graph": { "passes": [
      { "name": "lit", "type": "scene" },
      { "name": "noise", "type": "cloud_noise", "params": { "shape_size": 32, "detail_size": 16, "curl_size": 32 } },
      )" + weather_pass + R"(
      { "name": "march", "type": "cloud_march",
        "inputs": { "depth": "lit.depth", "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl")" + weather_input + R"( } },
      { "name": "shadow", "type": "cloud_shadow_map", "params": { "size": 16, "extent": 4000 },
        "inputs": { "shape": "noise.shape", "detail": "noise.detail", "curl": "noise.curl")" + weather_input + R"( } } ],
    "outputs": ["march.clouds", "shadow.optical_depth")" + (map.empty() ? "" : R"(, "weather.weather")") + R"(] } })";
}

struct WeatherRun {
  Texels clouds, tau, weather;
};

class CloudWeatherMap : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    register_builtin_passes(registry_);
    OnEachBackend::SetUp();
  }
  WeatherRun run(const std::string& map, double camera_x) {
    const LoadedConfig config = load_config_text("cloud_weather_map.json", weather_config_text(map, camera_x), registry_);
    Executor executor(device(), config.graph, &config.config.scene, {});
    executor.run_frame();
    WeatherRun r{executor.read_output(0), executor.read_output(1), {}};
    if (!map.empty()) r.weather = executor.read_output(2);
    return r;
  }
  PassRegistry registry_;
};

double mean_transmittance(const Texels& t) {
  double sum = 0;
  for (size_t i = 3; i < t.rgba.size(); i += 4) sum += t.rgba[i];
  return sum / double(t.rgba.size() / 4);
}

// Every value within fp16's rounding (2^-11 relative) of the other's, plus a tiny floor.
void expect_same_within_half(const Texels& a, const Texels& b, const std::string& what) {
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  for (size_t i = 0; i < a.rgba.size(); ++i)
    ASSERT_NEAR(a.rgba[i], b.rgba[i], 2e-3 * std::max(std::abs(a.rgba[i]), std::abs(b.rgba[i])) + 1e-6) << what << " value " << i;
}

// No cloud at all: radiance 0 and transmittance 1 exactly, τ 0 exactly.
void expect_clear(const WeatherRun& r, const std::string& what) {
  for (size_t i = 0; i < r.clouds.rgba.size(); i += 4) {
    ASSERT_EQ(r.clouds.rgba[i], 0.0f) << what << " pixel " << i / 4;
    ASSERT_EQ(r.clouds.rgba[i + 3], 1.0f) << what << " pixel " << i / 4;
  }
  for (size_t i = 0; i < r.tau.rgba.size(); i += 4) ASSERT_EQ(r.tau.rgba[i], 0.0f) << what << " texel " << i / 4;
}

TEST_P(CloudWeatherMap, WithoutAMapTheCaseSeesCloud) {  // so the identities below could fail
  const WeatherRun r = run("", 4000);
  EXPECT_LT(mean_transmittance(r.clouds), 0.9);
  const WeatherRun far = run("", 12000);
  EXPECT_LT(mean_transmittance(far.clouds), 0.9);
}

TEST_P(CloudWeatherMap, TheTextureHoldsTheImage) {
  const std::string map = write_map("gradient", [](int x, int y) { return std::array<uint8_t, 2>{uint8_t(16 * x), uint8_t(16 * y)}; });
  const Texels w = run(map, 4000).weather;
  ASSERT_EQ(w.width, uint32_t(kMapSide));
  for (int y = 0; y < kMapSide; ++y)
    for (int x = 0; x < kMapSide; ++x) {
      const float* t = &w.rgba[(size_t(y) * kMapSide + size_t(x)) * 4];
      EXPECT_FLOAT_EQ(t[0], float(16 * x) / 255.0f) << x << ", " << y;
      EXPECT_FLOAT_EQ(t[1], float(16 * y) / 255.0f) << x << ", " << y;
      EXPECT_FLOAT_EQ(t[3], 1.0f) << "a colour image's g is the type";
    }
}

TEST_P(CloudWeatherMap, AnAllWhiteMapDrawsWhatNoMapDraws) {
  const std::string map = write_map("white", [](int, int) { return std::array<uint8_t, 2>{255, kLayerType}; });
  for (const double x : {4000.0, 12000.0}) {
    const WeatherRun with = run(map, x), without = run("", x);
    expect_same_within_half(with.clouds, without.clouds, "clouds at x " + std::to_string(x));
    expect_same_within_half(with.tau, without.tau, "shadow τ at x " + std::to_string(x));
  }
}

TEST_P(CloudWeatherMap, AnAllBlackMapDrawsNoCloud) {
  const std::string map = write_map("black", [](int, int) { return std::array<uint8_t, 2>{0, kLayerType}; });
  expect_clear(run(map, 4000), "x 4000");
  expect_clear(run(map, 12000), "x 12000");
}

// Black over x in [0, 8 km) of each 16 km tile, white over [8, 16): the camera at x = 4 km sees
// its rays enter the layer over black (clear sky), at x = 12 km over white (cloud).
TEST_P(CloudWeatherMap, CloudsOnlyOverTheWhiteHalf) {
  const std::string map = write_map("halves", [](int x, int) { return std::array<uint8_t, 2>{uint8_t(x < kMapSide / 2 ? 0 : 255), kLayerType}; });
  const WeatherRun black = run(map, 4000), white = run(map, 12000);
  for (size_t i = 3; i < black.clouds.rgba.size(); i += 4) EXPECT_EQ(black.clouds.rgba[i], 1.0f) << "over black, pixel " << i / 4;
  EXPECT_LT(mean_transmittance(white.clouds), 0.9) << "over white";
  expect_same_within_half(white.clouds, run("", 12000).clouds, "over white: as without a map");
}

INSTANTIATE_TEST_SUITE_P(Backends, CloudWeatherMap, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
