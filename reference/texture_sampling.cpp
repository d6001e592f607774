#include "reference/texture_sampling.h"

#include <algorithm>
#include <cmath>

#include "physics/srgb.h"

namespace volgraph::reference {
namespace {

// A texel index of one axis under the wrap mode (Vulkan spec, "Wrapping Operation").
int64_t wrapped(int64_t i, int64_t size, rhi::AddressMode mode) {
  switch (mode) {
    case rhi::AddressMode::clamp_to_edge: return std::clamp<int64_t>(i, 0, size - 1);
    case rhi::AddressMode::repeat: return ((i % size) + size) % size;
    case rhi::AddressMode::mirror_repeat: {
      const int64_t period = ((i % (2 * size)) + 2 * size) % (2 * size);
      return period < size ? period : 2 * size - 1 - period;
    }
  }
  return 0;
}

}  // namespace

LinearImage linear_image(const plumbing::Rgba8Image& encoded) {
  LinearImage image{encoded.width, encoded.height, {}};
  image.rgb.resize(size_t(encoded.width) * encoded.height * 3);
  image.alpha.resize(size_t(encoded.width) * encoded.height);
  for (size_t texel = 0; texel < size_t(encoded.width) * encoded.height; ++texel) {
    for (size_t c = 0; c < 3; ++c) image.rgb[texel * 3 + c] = physics::srgb_decode(encoded.texels[texel * 4 + c] / 255.0f);
    image.alpha[texel] = encoded.texels[texel * 4 + 3] / 255.0f;
  }
  return image;
}

LinearImage data_image(const plumbing::Rgba8Image& stored) {
  LinearImage image{stored.width, stored.height, {}};
  image.rgb.resize(size_t(stored.width) * stored.height * 3);
  image.alpha.resize(size_t(stored.width) * stored.height);
  for (size_t texel = 0; texel < size_t(stored.width) * stored.height; ++texel) {
    for (size_t c = 0; c < 3; ++c) image.rgb[texel * 3 + c] = stored.texels[texel * 4 + c] / 255.0f;
    image.alpha[texel] = stored.texels[texel * 4 + 3] / 255.0f;
  }
  return image;
}

Vec3 sample_bilinear(const LinearImage& image, plumbing::SamplerWrap wrap, double u, double v) {
  if (image.width == 0 || image.height == 0 || !std::isfinite(u) || !std::isfinite(v)) return {1, 1, 1};
  const double x = u * image.width - 0.5, y = v * image.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  Vec3 sum{0, 0, 0};
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const int64_t column = wrapped(int64_t(x0) + dx, image.width, wrap.u);
      const int64_t row = wrapped(int64_t(y0) + dy, image.height, wrap.v);
      const double weight = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy);
      const size_t at = (size_t(row) * image.width + size_t(column)) * 3;
      for (size_t c = 0; c < 3; ++c) sum[c] += weight * image.rgb[at + c];
    }
  }
  return sum;
}

double sample_alpha_bilinear(const LinearImage& image, plumbing::SamplerWrap wrap, double u, double v) {
  if (image.width == 0 || image.height == 0 || image.alpha.size() != size_t(image.width) * image.height || !std::isfinite(u) ||
      !std::isfinite(v)) {
    return 1;
  }
  const double x = u * image.width - 0.5, y = v * image.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  double sum = 0;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const int64_t column = wrapped(int64_t(x0) + dx, image.width, wrap.u);
      const int64_t row = wrapped(int64_t(y0) + dy, image.height, wrap.v);
      sum += (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy) * image.alpha[size_t(row) * image.width + size_t(column)];
    }
  }
  return sum;
}

}  // namespace volgraph::reference
