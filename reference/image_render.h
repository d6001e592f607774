// A whole reference image: pixels shared among threads a row at a time (pulled from an
// atomic counter), each pixel computed alone, so the image is the same bit for bit with
// any number of threads; an optional one-line progress percentage.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <vector>

#include "reference/renderer.h"

namespace volgraph::reference {

struct RenderSettings {
  uint32_t width = 320, height = 180;
  uint32_t samples_per_axis = 1;  // sub-pixel samples per axis (spp = its square)
  unsigned threads = 0;           // 0: std::thread::hardware_concurrency(); fewer when the system gives fewer
  std::ostream* progress = nullptr;  // "\rreference: N %" lines while rendering, if set
};

struct ReferenceImage {
  uint32_t width = 0, height = 0;
  std::vector<double> rgb;  // linear radiance, 3 a pixel, row 0 at the top
  Vec3 at(uint32_t i, uint32_t j) const {
    const size_t k = (size_t(j) * width + i) * 3;
    return {rgb[k], rgb[k + 1], rgb[k + 2]};
  }
};

ReferenceImage render_image(const Renderer& renderer, const RenderSettings& settings);
// The same threading for any per-pixel function (i, j) → radiance (samples_per_axis is
// the function's business).
ReferenceImage render_pixels(const std::function<Vec3(uint32_t, uint32_t)>& pixel, const RenderSettings& settings);

}  // namespace volgraph::reference
