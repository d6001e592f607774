// Material textures: mip chains averaged in linear light (not in sRGB-encoded values),
// their sizes down to 1×1, and images decoded or refused with a reason.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include "physics/srgb.h"
#include "graph/diagnostics.h"
#include "passes/plumbing/textures.h"
#include "tests/support/source_dir.h"

namespace volgraph::plumbing {

namespace {

Rgba8Image image(uint32_t width, uint32_t height, std::vector<uint8_t> texels) { return {width, height, std::move(texels)}; }

TEST(Textures, MipChainAveragesInLinearLight) {
  // A 2×2 block of black and white: the mean in linear light is 0.5, encoded 0.7354 →
  // 188, not the 128 a mean of encoded values would give. Alpha is linear: 127.5 → 128.
  const Rgba8Image top = image(2, 2, {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0});
  const std::vector<Rgba8Image> chain = srgb_mip_chain(top);
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[0].texels, top.texels);
  EXPECT_EQ(chain[1].width, 1u);
  EXPECT_EQ(chain[1].texels, (std::vector<uint8_t>{188, 188, 188, 128}));
  EXPECT_EQ(std::lround(physics::srgb_encode(0.5f) * 255), 188);
}

// Data stored linear (glTF's transmission and thickness textures): the same block's mean is
// the stored values' mean, 127.5 → 128 in every channel, not sRGB's 188.
TEST(Textures, ADataTexturesMipIsTheMeanOfItsStoredValues) {
  const Rgba8Image top = image(2, 2, {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0});
  const std::vector<Rgba8Image> chain = linear_mip_chain(top);
  ASSERT_EQ(chain.size(), 2u);
  EXPECT_EQ(chain[0].texels, top.texels);
  EXPECT_EQ(chain[1].texels, (std::vector<uint8_t>{128, 128, 128, 128}));
}

TEST(Textures, MipChainGoesDownToOneTexelFromAnySize) {
  const std::vector<Rgba8Image> chain = srgb_mip_chain(image(5, 3, std::vector<uint8_t>(5 * 3 * 4, 200)));
  ASSERT_EQ(chain.size(), 3u);  // 5×3, 2×1, 1×1
  EXPECT_EQ(chain[1].width, 2u);
  EXPECT_EQ(chain[1].height, 1u);
  EXPECT_EQ(chain[2].width, 1u);
  EXPECT_EQ(chain[2].height, 1u);
  for (const Rgba8Image& level : chain) {
    for (uint8_t v : level.texels) ASSERT_EQ(v, 200);  // a constant image stays constant
  }
}

TEST(Textures, DecodesAPngToRgbaWithRowZeroAtTheTop) {
  // 1×2 RGB PNG: red over blue, written by stb_image_write.
  const uint8_t rgb[] = {255, 0, 0, 0, 0, 255};
  std::vector<uint8_t> png;
  stbi_write_png_to_func([](void* out, void* data, int size) {
    auto* bytes = static_cast<uint8_t*>(data);
    static_cast<std::vector<uint8_t>*>(out)->insert(static_cast<std::vector<uint8_t>*>(out)->end(), bytes, bytes + size);
  }, &png, 1, 2, 3, rgb, 3);
  EXPECT_EQ(image_problem(png.data(), png.size()), "");
  const Rgba8Image decoded = decode_image(png.data(), png.size(), "test.png");
  EXPECT_EQ(decoded.width, 1u);
  EXPECT_EQ(decoded.height, 2u);
  EXPECT_EQ(decoded.texels, (std::vector<uint8_t>{255, 0, 0, 255, 0, 0, 255, 255}));
}

TEST(Textures, RefusesWhatIsNotAnImageAndSaysWhy) {
  const std::string text = "not an image at all";
  const auto* bytes = reinterpret_cast<const uint8_t*>(text.data());
  EXPECT_NE(image_problem(bytes, text.size()).find("not an image volgraph reads"), std::string::npos);
  EXPECT_THROW(decode_image(bytes, text.size(), "x.png"), ConfigError);  // the user's file: bad input, exit 2
  EXPECT_NE(image_file_problem("/no/such/file.png").find("cannot open"), std::string::npos);
}

// PNGs whose header is fine but whose texels cannot be decoded: found without decoding.
TEST(Textures, RefusesATruncatedOrDamagedPngFromItsChunks) {
  const std::string dir = std::string(::volgraph::testing::source_dir()) + "/tests/cli/bad/textures/";
  EXPECT_NE(image_file_problem(dir + "truncated.png").find("a truncated PNG"), std::string::npos) << image_file_problem(dir + "truncated.png");
  EXPECT_NE(image_file_problem(dir + "bad_crc.png").find("chunk IDAT at byte 33 fails its CRC"), std::string::npos)
      << image_file_problem(dir + "bad_crc.png");
  // The damage is real: stb_image cannot decode either.
  for (const char* name : {"truncated.png", "bad_crc.png"}) EXPECT_THROW(read_image_file(dir + name), ConfigError) << name;
}

}  // namespace
}  // namespace volgraph::plumbing
