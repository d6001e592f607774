// Bilinear sampling of level 0 in linear light: texel centres give the decoded texel
// exactly, half-way points the mean of neighbours, and the wrap modes pick the texels
// the Vulkan specification's wrapping operation does.
#include <gtest/gtest.h>

#include "physics/srgb.h"
#include "reference/texture_sampling.h"

namespace volgraph::reference {
namespace {

// A 2×1 image: black, then white (sRGB 255 decodes to exactly 1).
LinearImage black_white() {
  plumbing::Rgba8Image encoded{2, 1, {0, 0, 0, 255, 255, 255, 255, 255}};
  return linear_image(encoded);
}

TEST(TextureSampling, DecodesSrgbOnce) {
  const LinearImage image = linear_image({1, 1, {128, 64, 255, 255}});
  EXPECT_EQ(image.rgb[0], physics::srgb_decode(128 / 255.0f));
  EXPECT_EQ(image.rgb[1], physics::srgb_decode(64 / 255.0f));
  EXPECT_EQ(image.rgb[2], 1.0f);
}

TEST(TextureSampling, TexelCentresAndMidpoints) {
  const LinearImage image = black_white();
  const plumbing::SamplerWrap clamp{rhi::AddressMode::clamp_to_edge, rhi::AddressMode::clamp_to_edge};
  EXPECT_EQ(sample_bilinear(image, clamp, 0.25, 0.5)[0], 0.0);
  EXPECT_EQ(sample_bilinear(image, clamp, 0.75, 0.5)[0], 1.0);
  EXPECT_EQ(sample_bilinear(image, clamp, 0.5, 0.5)[0], 0.5);
  EXPECT_EQ(sample_bilinear(image, clamp, 0.375, 0.5)[0], 0.25);
  EXPECT_EQ(sample_bilinear(image, clamp, 0.0, 0.5)[0], 0.0);  // clamped: the edge texel alone
}

TEST(TextureSampling, WrapModes) {
  const LinearImage image = black_white();
  const plumbing::SamplerWrap repeat{rhi::AddressMode::repeat, rhi::AddressMode::repeat};
  const plumbing::SamplerWrap mirror{rhi::AddressMode::mirror_repeat, rhi::AddressMode::mirror_repeat};
  EXPECT_EQ(sample_bilinear(image, repeat, 0.0, 0.5)[0], 0.5);    // between the last and the first texel
  EXPECT_EQ(sample_bilinear(image, repeat, 1.25, 0.5)[0], 0.0);   // one period on
  EXPECT_EQ(sample_bilinear(image, mirror, 1.25, 0.5)[0], 1.0);   // mirrored: white comes first
  EXPECT_EQ(sample_bilinear(image, mirror, 0.0, 0.5)[0], 0.0);    // the edge texel and its mirror image
}

}  // namespace
}  // namespace volgraph::reference
