// volume_file's reader (passes/volume/volume_file_reader.h): NRRD headers of each sample
// type, both endians, attached and detached data, spacings and axis-aligned space
// directions; the samples read back exactly; each bad header refused with what was expected;
// the window's mapping to [0, 1]; the box's proportions from sizes × spacing.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "passes/volume/volume_file_reader.h"
#include "tests/support/nrrd_writer.h"

namespace volgraph::volume_file {
namespace {

const std::string kSizes = "dimension: 3\nsizes: 2 3 4\nencoding: raw\n";

// The reader's message for a header, or "" when it reads.
std::string refusal(const std::string& fields) {
  try {
    parse_nrrd_header("NRRD0004\n" + fields + "\n", "/data/v.nrrd");
  } catch (const VolumeFileError& e) {
    return e.what();
  }
  return "";
}

TEST(VolumeFile, EachSampleTypeAndEndianReadsBackExactly) {
  const test::TempFolder folder("volume_file_types");
  std::vector<uint8_t> u8(24);
  std::vector<uint16_t> u16(24);
  std::vector<int16_t> i16(24);
  std::vector<float> f32(24);
  for (size_t i = 0; i < 24; ++i) {
    u8[i] = uint8_t(i * 11), u16[i] = uint16_t(i * 2731), i16[i] = int16_t(int(i) * 2731 - 32768), f32[i] = float(i) / 23.0f - 0.25f;
  }
  struct Case {
    std::string type, endian;
    std::vector<char> bytes;
    std::vector<float> want;
  };
  const std::vector<Case> cases{
      {"uchar", "", test::sample_bytes(u8), {u8.begin(), u8.end()}},
      {"unsigned short", "little", test::sample_bytes(u16), {u16.begin(), u16.end()}},
      {"ushort", "big", test::sample_bytes(u16, true), {u16.begin(), u16.end()}},
      {"short", "big", test::sample_bytes(i16, true), {i16.begin(), i16.end()}},
      {"int16", "little", test::sample_bytes(i16), {i16.begin(), i16.end()}},
      {"float", "big", test::sample_bytes(f32, true), f32},
      {"float", "little", test::sample_bytes(f32), f32},
  };
  for (const Case& c : cases) {
    const std::string path = folder.file("v.nrrd");
    test::write_nrrd(path, "type: " + c.type + "\n" + kSizes + (c.endian.empty() ? "" : "endian: " + c.endian + "\n"), c.bytes);
    const VolumeLayout layout = read_nrrd_layout(path);
    EXPECT_EQ(layout.sizes, (std::array<uint32_t, 3>{2, 3, 4})) << c.type;
    EXPECT_EQ(layout.big_endian, c.endian == "big") << c.type;
    EXPECT_EQ(read_samples(layout), c.want) << c.type << " " << c.endian;
  }
}

TEST(VolumeFile, DetachedDataIsReadBesideTheHeader) {
  const test::TempFolder folder("volume_file_detached");
  const std::vector<uint8_t> values{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24};
  test::write_bytes(folder.file("samples.raw"), "", test::sample_bytes(values));
  test::write_bytes(folder.file("v.nhdr"), "NRRD0005\ntype: uchar\n" + kSizes + "data file: samples.raw\n", {});
  const VolumeLayout layout = read_nrrd_layout(folder.file("v.nhdr"));
  EXPECT_EQ(layout.data_file, folder.file("samples.raw"));
  EXPECT_EQ(layout.data_offset, 0u);
  EXPECT_EQ(read_samples(layout), std::vector<float>(values.begin(), values.end()));
}

TEST(VolumeFile, SpacingsAndSpaceDirectionsGiveTheSpacing) {
  const std::string head = "NRRD0004\ntype: uchar\n" + kSizes;
  EXPECT_EQ(parse_nrrd_header(head + "spacings: 0.5 0.5 2\n\n", "v.nrrd").spacing, (std::array<double, 3>{0.5, 0.5, 2}));
  EXPECT_EQ(parse_nrrd_header(head + "space: RAS\nspace directions: (0.7,0,0) (0,-0.7,0) (0,0,1.5)\n\n", "v.nrrd").spacing,
            (std::array<double, 3>{0.7, 0.7, 1.5}))
      << "a flipped axis keeps its spacing";
  EXPECT_EQ(parse_nrrd_header(head + "\n", "v.nrrd").spacing, (std::array<double, 3>{1, 1, 1})) << "no spacing: 1";
  const VolumeLayout attached = parse_nrrd_header(head + "# a comment\nkey:=value\n\n", "v.nrrd");
  EXPECT_EQ(attached.data_offset, (head + "# a comment\nkey:=value\n\n").size()) << "the data starts after the blank line";
}

TEST(VolumeFile, BadHeadersSayWhatWasExpected) {
  EXPECT_EQ(refusal("type: uchar\n" + kSizes), "") << "a good header reads";
  const auto refused = [](const std::string& fields, const std::string& expected) {
    const std::string message = refusal(fields);
    EXPECT_NE(message.find(expected), std::string::npos) << "header:\n" << fields << "message: " << message;
  };
  refused("type: uchar\ndimension: 3\nsizes: 2 3 4\nencoding: gzip\n", "encoding: gzip is not read, expected raw");
  refused("type: double\n" + kSizes, "expected uchar, ushort, short or float");
  refused("type: uchar\ndimension: 2\nsizes: 2 3\nencoding: raw\n", "expected 3");
  refused("type: uchar\ndimension: 3\nsizes: 2 3\nencoding: raw\n", "sizes: expected three sizes");
  refused("type: ushort\n" + kSizes, "no \"endian:\" field");
  refused("type: uchar\n" + kSizes + "space directions: (1,0.5,0) (0,1,0) (0,0,1)\n", "only axis-aligned volumes");
  refused("type: uchar\n" + kSizes + "spacings: 1 0 1\n", "spacings above 0");
  refused("type: uchar\ndimension: 3\nsizes: 2 3 4\n", "no \"encoding:\" field");
  refused("type: uchar\n" + kSizes + "data file: LIST\n", "no lists or patterns");
  EXPECT_EQ(refusal("type: ushort\n" + kSizes).rfind("/data/v.nrrd: ", 0), 0u) << "the message starts with the file";
  try {
    parse_nrrd_header("P6\n", "v.ppm");
    FAIL() << "a PPM read as NRRD";
  } catch (const VolumeFileError& e) {
    EXPECT_NE(std::string(e.what()).find("not a NRRD file"), std::string::npos) << e.what();
  }
}

TEST(VolumeFile, DataOfAnotherSizeThanTheHeaderSaysIsRefused) {
  const test::TempFolder folder("volume_file_size");
  for (const size_t count : {23, 25}) {
    test::write_nrrd(folder.file("v.nrrd"), "type: uchar\n" + kSizes, std::vector<char>(count, 7));
    try {
      read_samples(read_nrrd_layout(folder.file("v.nrrd")));
      FAIL() << count << " samples for 2 × 3 × 4 read";
    } catch (const VolumeFileError& e) {
      EXPECT_NE(std::string(e.what()).find("holds " + std::to_string(count) + " bytes of samples, expected 24"), std::string::npos) << e.what();
    }
  }
}

TEST(VolumeFile, TheWindowMapsToTheUnitInterval) {
  EXPECT_EQ(normalised({0, 51, 255}, scalar_type_range(ScalarType::uchar)), (std::vector<float>{0, 0.2f, 1}));
  EXPECT_EQ(normalised({-32768, 32767}, scalar_type_range(ScalarType::short_)), (std::vector<float>{0, 1}));
  EXPECT_EQ(normalised({100, 150, 200, 50, 300}, {100, 200}), (std::vector<float>{0, 0.5f, 1, 0, 1})) << "clamped outside";
}

TEST(VolumeFile, TheBoxFollowsSizesTimesSpacing) {
  VolumeLayout layout;
  layout.sizes = {256, 256, 128};
  layout.spacing = {1, 1, 2};
  EXPECT_EQ(box_proportions(layout), (std::array<double, 3>{1, 1, 1})) << "256 × 256 × 128 at spacing 1, 1, 2 is a cube";
  layout.spacing = {1, 1, 1};
  EXPECT_EQ(box_proportions(layout), (std::array<double, 3>{1, 1, 0.5})) << "at spacing 1, 1, 1 half as tall";
}

}  // namespace
}  // namespace volgraph::volume_file
