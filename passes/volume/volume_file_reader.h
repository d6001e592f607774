// Scalar volume files for volume_file (RTR4 14.3.1): a NRRD file (NRRD0001–NRRD0005, the
// Teem format: a text header, a blank line, then the samples, or the samples in a detached
// `data file:`) or a headerless .raw file whose layout the config gives. Only what a scalar
// 3D texture needs: `dimension: 3`, `type` uchar / ushort / short / float, `encoding: raw`,
// `endian`, `sizes`, and `spacings` or axis-aligned `space directions`. Anything else is
// refused with a message saying what was expected (VolumeFileError). Graph-independent.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace volgraph {
struct VolumeData;
}

namespace volgraph::volume_file {

// A problem with a volume file: the message says what was read and what was expected.
struct VolumeFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class ScalarType : uint8_t { uchar, ushort, short_, float_ };

struct VolumeLayout {
  ScalarType type = ScalarType::uchar;
  std::array<uint32_t, 3> sizes{1, 1, 1};      // samples along x (fastest), y, z
  std::array<double, 3> spacing{1, 1, 1};      // the distance between samples along each axis (any unit)
  bool big_endian = false;                     // multi-byte types only
  std::string data_file;                       // the samples' file (the header's own for attached data)
  uint64_t data_offset = 0;                    // the samples' first byte in data_file
};

// The bytes of one sample of `type`.
size_t scalar_bytes(ScalarType type);
// The type's NRRD name (uchar, ushort, short, float).
std::string scalar_type_name(ScalarType type);
// A type by its NRRD name or one of NRRD's synonyms (unsigned char, uint8, uint16, int16, …).
ScalarType scalar_type_named(const std::string& name);
// The values a type spans, for normalising to [0, 1]: uchar 0–255, ushort 0–65535,
// short −32768–32767; float 0–1 (floats are taken as already normalised).
std::array<double, 2> scalar_type_range(ScalarType type);

// The layout of the NRRD file at `path` (its header; a detached data file relative to it).
VolumeLayout read_nrrd_layout(const std::string& path);
// The layout of a NRRD header given as text (`path` names the header's file, for a
// detached data file and the attached data's offset: the byte after the blank line).
VolumeLayout parse_nrrd_header(const std::string& text, const std::string& path);

// The samples of a layout as floats, x fastest, in the file's units; refuses a data file
// shorter than sizes × the type's bytes (past the offset) or a longer one (a wrong layout).
std::vector<float> read_samples(const VolumeLayout& layout);

// The samples mapped to [0, 1]: (v − low) / (high − low), clamped.
std::vector<float> normalised(const std::vector<float>& samples, std::array<double, 2> window);

// The box's sides in proportion to size × spacing, the longest 1 (a 256×256×128 volume
// with spacing 1, 1, 2 is a cube; with 1, 1, 1 half as tall as wide).
std::array<double, 3> box_proportions(const VolumeLayout& layout);

// The layout of the scene's volume file: its NRRD header's, or the config's for a .raw file.
VolumeLayout volume_layout(const VolumeData& volume);
// The window its samples map to [0, 1] through: the config's, else the type's range.
std::array<double, 2> volume_window(const VolumeData& volume, const VolumeLayout& layout);

}  // namespace volgraph::volume_file
