// Image files: row 0 at the top in every format, PNG's sRGB encoding exact, EXR and PFM
// lossless for float data, a failed write (a full disk included) leaving no file behind,
// and outputs renamed into place together.
#include <filesystem>
#include <fstream>
#include <span>

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include "graph/diagnostics.h"
#include "physics/srgb.h"
#include "tools/image_io.h"
#include "tools/output_files.h"

namespace volgraph {
namespace {

// 3x2 pixels: the top row red, green, blue; the bottom row values HDR and tiny.
Image test_image() {
  Image im;
  im.width = 3;
  im.height = 2;
  im.rgba = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1,
             12.5f, 0.5f, 1e-4f, 1, 0.0031308f, 0.2159f, 1e6f, 1, 0, 0, 0, 0.5f};
  return im;
}

class ImageIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("volgraph_image_io_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  size_t files() const { return size_t(std::distance(std::filesystem::directory_iterator(dir_), {})); }
  std::filesystem::path dir_;
};

TEST_F(ImageIo, PfmRoundTripsAndStoresTheTopRowLast) {
  const Image im = test_image();
  write_image(path("a.pfm"), im);
  const Image back = read_pfm(path("a.pfm"));
  ASSERT_EQ(back.width, 3u);
  ASSERT_EQ(back.height, 2u);
  for (size_t i = 0; i < im.rgba.size(); ++i) {
    if (i % 4 != 3) EXPECT_EQ(back.rgba[i], im.rgba[i]) << i;
  }
  // The file's last scanline is row 0: its first float is the top-left red.
  std::ifstream f(path("a.pfm"), std::ios::binary | std::ios::ate);
  const auto size = f.tellg();
  f.seekg(size - std::streamoff(3 * 3 * sizeof(float)));
  float first_of_last_row = 0;
  f.read(reinterpret_cast<char*>(&first_of_last_row), sizeof(float));
  EXPECT_EQ(first_of_last_row, 1.0f);
}

TEST_F(ImageIo, PngIsSrgbEncodedWithRowZeroAtTheTop) {
  write_image(path("a.png"), test_image());
  int w = 0, h = 0, n = 0;
  stbi_uc* px = stbi_load(path("a.png").c_str(), &w, &h, &n, 4);
  ASSERT_NE(px, nullptr);
  EXPECT_EQ(w, 3);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(px[0], 255);  // top-left red
  EXPECT_EQ(px[1], 0);
  EXPECT_EQ(px[4 * 3 + 0], 255);  // HDR clamps to white
  EXPECT_EQ(px[4 * 3 + 1], 188);  // linear 0.5 → sRGB 0.7354 → 188
  EXPECT_EQ(px[4 * 4 + 0], 10);   // the linear toe: 12.92 × 0.0031308 × 255 = 10.3
  EXPECT_EQ(px[4 * 4 + 1], 128);  // linear 0.2159 → sRGB 0.5020 → 128.01
  EXPECT_EQ(px[4 * 5 + 3], 128);  // alpha 0.5, not encoded
  stbi_image_free(px);
}

TEST_F(ImageIo, ExrKeepsFloatsExactly) {
  const Image im = test_image();
  write_image(path("a.exr"), im);
  Imf::InputFile in(path("a.exr").c_str());
  const auto window = in.header().dataWindow();
  ASSERT_EQ(window.max.x - window.min.x + 1, 3);
  ASSERT_EQ(window.max.y - window.min.y + 1, 2);
  std::vector<float> rgba(24);
  Imf::FrameBuffer frame;
  const char* names[] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c) {
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgba.data() + c), 16, 3 * 16));
  }
  in.setFrameBuffer(frame);
  in.readPixels(window.min.y, window.max.y);
  EXPECT_EQ(rgba, im.rgba);  // EXR's y grows downwards: row 0 is the top
}

TEST_F(ImageIo, UnsupportedTypeIsBadInputAndWritesNothing) {
  try {
    write_image(path("a.jpg"), test_image());
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a .png, .exr or .pfm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("-o "), std::string::npos) << e.what();
  }
  EXPECT_EQ(files(), 0u);
}

TEST_F(ImageIo, MissingFolderIsBadInputAndWritesNothing) {
  EXPECT_THROW(write_image(path("no/such/folder/a.pfm"), test_image()), ConfigError);
  EXPECT_EQ(files(), 0u);
}

TEST_F(ImageIo, AFailedWriteLeavesNoTemporaryFile) {
  // A folder where the file should go: the rename fails after the temporary was written.
  std::filesystem::create_directories(dir_ / "taken.pfm" / "inside");
  EXPECT_THROW(write_image(path("taken.pfm"), test_image()), ConfigError);
  EXPECT_EQ(files(), 1u);  // only the folder that was in the way
}

// A full disk: /dev/full takes the open and fails the writes (ENOSPC), which the
// stdio buffer reports only at the flush.
TEST(WriteFileChecked, AFullDiskIsAnIoErrorNamingTheFile) {
  for (const ImageFormat format : {ImageFormat::png, ImageFormat::exr, ImageFormat::pfm}) {
    const std::vector<std::byte> bytes = encode_image(test_image(), format);
    ASSERT_FALSE(bytes.empty());
    try {
      write_file_checked("/dev/full", bytes);
      ADD_FAILURE() << "expected an IoError";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find("/dev/full: No space left on device"), std::string::npos) << e.what();
    }
  }
}

TEST_F(ImageIo, EncodedPngIsTheImage) {
  const std::vector<std::byte> bytes = encode_image(test_image(), ImageFormat::png);
  int w = 0, h = 0, n = 0;
  stbi_uc* texels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &n, 4);
  ASSERT_NE(texels, nullptr);
  EXPECT_EQ(w, 3);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(texels[0], 255);  // the top-left texel is red
  EXPECT_EQ(texels[1], 0);
  stbi_image_free(texels);
}

// Outputs are all or none: the first is not in place when a later one fails.
TEST_F(ImageIo, OutputFilesRenameNothingUntilEveryFileIsWritten) {
  const std::vector<std::byte> bytes = encode_image(test_image(), ImageFormat::pfm);
  {
    OutputFiles outputs;
    outputs.stage(path("first.pfm"), "-o", bytes);
    EXPECT_THROW(outputs.stage(path("no/such/folder/second.pfm"), "--dump", bytes), ConfigError);
  }  // never committed: the temporary is removed
  EXPECT_EQ(files(), 0u);
  OutputFiles outputs;
  outputs.stage(path("first.pfm"), "-o", bytes);
  const std::string timings = "{}";
  outputs.stage(path("second.json"), "--timings-out", std::as_bytes(std::span(timings)));
  EXPECT_EQ(files(), 2u);  // two temporaries, no target yet
  EXPECT_FALSE(std::filesystem::exists(path("first.pfm")));
  outputs.commit();
  EXPECT_TRUE(std::filesystem::exists(path("first.pfm")));
  EXPECT_TRUE(std::filesystem::exists(path("second.json")));
  EXPECT_EQ(files(), 2u);
}

TEST(Srgb, MatchesTheStandardAtItsKnots) {
  using physics::srgb_encode, physics::srgb_decode;
  EXPECT_FLOAT_EQ(srgb_encode(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgb_encode(1.0f), 1.0f);
  EXPECT_NEAR(srgb_encode(0.0031308f), 0.040449936f, 1e-6);
  EXPECT_NEAR(srgb_encode(0.5f), 0.735356983f, 1e-6);
  EXPECT_EQ(srgb_encode(-1.0f), 0.0f);
  EXPECT_NEAR(srgb_decode(0.735356983f), 0.5f, 1e-6);
  EXPECT_NEAR(srgb_decode(0.04045f), 0.0031308f, 1e-7);
  for (int i = 0; i <= 255; ++i) EXPECT_NEAR(srgb_encode(srgb_decode(float(i) / 255)), float(i) / 255, 1e-6) << i;
}

}  // namespace
}  // namespace volgraph
