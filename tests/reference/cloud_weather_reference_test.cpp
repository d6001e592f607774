// The CPU reference's weather map (reference/clouds.cpp; docs/clouds.md "Weather map"): the
// texture cloud_weather_map stores, sampled as cloud_layer.glsl does. A map black over
// x in [0, 8 km) of each 16 km tile and white (r = 1, g = the layer's type) over [8, 16): no
// density at all over the black half, the map-less density over the white half (within the
// bilinear weights' float rounding).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "reference/clouds.h"
#include "tools/image_io.h"

namespace volgraph::reference {
namespace {

constexpr uint32_t kSide = 16;

std::string write_halves_map() {
  std::vector<uint8_t> rgba;
  for (uint32_t y = 0; y < kSide; ++y)
    for (uint32_t x = 0; x < kSide; ++x) rgba.insert(rgba.end(), {uint8_t(x < kSide / 2 ? 0 : 255), 153, 0, 255});
  const std::vector<std::byte> png = encode_png_rgba8(kSide, kSide, rgba);
  const std::string path = (std::filesystem::path(::testing::TempDir()) / "cloud_weather_reference_halves.png").string();
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
  return path;
}

Scene weather_scene(bool with_map) {
  Scene s;
  s.camera.position = {0, 2, 0};
  s.clouds = CloudLayer{.coverage = 0.8, .type = 0.6, .extinction = 0.06, .shape_scale = 20000, .detail_scale = 2500, .wind = {0, 0, 0}};
  if (with_map) s.clouds->weather_map = CloudWeatherMap{.image = write_halves_map(), .size = 16000};
  return s;
}

TEST(CloudWeatherReference, NoDensityOverTheBlackHalfTheMaplessOneOverTheWhite) {
  CloudReferenceSettings k;
  k.shape_size = 32, k.detail_size = 16, k.curl_size = 32, k.weather_size = int(kSide);
  const CloudReference with(weather_scene(true), k), without(weather_scene(false), k);
  double white_sum = 0;
  for (double altitude = 1600; altitude < 4000; altitude += 300)
    for (double z = -8000; z <= 8000; z += 1000) {
      for (double x = 1000; x <= 7000; x += 500) ASSERT_EQ(with.density({x, altitude, z}), 0.0) << x << ", " << altitude << ", " << z;
      for (double x = 9000; x <= 15000; x += 500) {
        const double d = with.density({x, altitude, z});
        ASSERT_NEAR(d, without.density({x, altitude, z}), 1e-5 * d + 1e-9) << x << ", " << altitude << ", " << z;
        white_sum += d;
      }
    }
  EXPECT_GT(white_sum, 0.0) << "the white half has cloud, so the black half's zeros could fail";
}

}  // namespace
}  // namespace volgraph::reference
