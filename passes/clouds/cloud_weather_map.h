// The weather map's texture and lookup, one text for cloud_weather_map (the GPU's texture),
// cloud_march / cloud_shadow_map (the lookup's parameters) and the CPU reference
// (reference/clouds.cpp): docs/clouds.md "Weather map".
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "graph/scene/scene.h"
#include "passes/plumbing/textures.h"

namespace volgraph::clouds {

// Whether the image carries a cloud type in g (a colour image); a grey one: the layer's type.
inline bool weather_has_type(const plumbing::Rgba8Image& image) { return image.channels >= 3; }

// The texture's rgba8 texels, `size` × `size`, row 0 the image's top: r, g the image
// resampled bilinearly with repeat at the texel centres (the image itself when it is
// size × size), b 0, a 255 where g is the type (a colour image), 0 where the layer's type
// holds (a grey one): the shaders' type is mix(layer type, g, a). The GPU and the reference
// hold the same bytes.
inline std::vector<uint8_t> weather_texels(const plumbing::Rgba8Image& image, uint32_t size) {
  std::vector<uint8_t> out(size_t(size) * size * 4);
  const auto at = [&](int64_t x, int64_t y, int c) {
    const int64_t w = image.width, h = image.height;
    return float(image.texels[(size_t(((y % h) + h) % h) * size_t(w) + size_t(((x % w) + w) % w)) * 4 + size_t(c)]);
  };
  for (uint32_t j = 0; j < size; ++j) {
    for (uint32_t i = 0; i < size; ++i) {
      const double x = (i + 0.5) * image.width / size - 0.5, y = (j + 0.5) * image.height / size - 0.5;
      const int64_t x0 = int64_t(std::floor(x)), y0 = int64_t(std::floor(y));
      const float fx = float(x - double(x0)), fy = float(y - double(y0));
      for (int c = 0; c < 2; ++c) {
        const float top = at(x0, y0, c) * (1 - fx) + at(x0 + 1, y0, c) * fx;
        const float bottom = at(x0, y0 + 1, c) * (1 - fx) + at(x0 + 1, y0 + 1, c) * fx;
        out[(size_t(j) * size + i) * 4 + size_t(c)] = uint8_t(std::lround(std::clamp(top * (1 - fy) + bottom * fy, 0.0f, 255.0f)));
      }
      out[(size_t(j) * size + i) * 4 + 3] = weather_has_type(image) ? 255 : 0;
    }
  }
  return out;
}

// The shaders' `weather` parameter (cloud_layer.glsl's cloud_weather): x 1 / size (1/m),
// y, z the offset (m); all 0 without a map.
inline std::array<float, 4> weather_lookup(const CloudLayer& layer) {
  if (!layer.weather_map) return {0, 0, 0, 0};
  const CloudWeatherMap& map = *layer.weather_map;
  return {float(1.0 / map.size), float(map.offset[0]), float(map.offset[1]), 0};
}

}  // namespace volgraph::clouds
