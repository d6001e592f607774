// NRRD headers (http://teem.sourceforge.net/nrrd/format.html, NRRD0001–NRRD0005) and raw
// samples for volume_file: passes/volume/volume_file_reader.h.
#include "passes/volume/volume_file_reader.h"

#include "graph/scene/scene.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace volgraph::volume_file {
namespace {

std::string trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

[[noreturn]] void refuse(const std::string& path, const std::string& message) { throw VolumeFileError(path + ": " + message); }

// The header's fields ("key: value"), keys lower case; the byte after the blank line that
// ends the header (0 when the text has none).
struct HeaderFields {
  std::map<std::string, std::string> fields;
  uint64_t data_offset = 0;
};

HeaderFields header_fields(const std::string& text, const std::string& path) {
  if (text.rfind("NRRD000", 0) != 0 || text.size() < 8 || text[7] < '1' || text[7] > '5')
    refuse(path, "not a NRRD file: expected the magic NRRD0001 … NRRD0005 on the first line");
  HeaderFields h;
  size_t at = text.find('\n');
  while (at != std::string::npos && at + 1 <= text.size()) {
    const size_t begin = at + 1;
    const size_t end = text.find('\n', begin);
    const std::string line = trimmed(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if (line.empty()) {
      if (end != std::string::npos || begin < text.size()) h.data_offset = end == std::string::npos ? text.size() : end + 1;
      break;
    }
    at = end;
    if (line[0] == '#' || line.find(":=") != std::string::npos) continue;  // a comment, a key/value pair
    const size_t colon = line.find(": ");
    if (colon == std::string::npos) refuse(path, "expected a header field \"name: value\", got \"" + line + "\"");
    h.fields[lower(line.substr(0, colon))] = trimmed(line.substr(colon + 2));
  }
  return h;
}

const std::string& required(const HeaderFields& h, const std::string& key, const std::string& path) {
  const auto found = h.fields.find(key);
  if (found == h.fields.end()) refuse(path, "the header has no \"" + key + ":\" field");
  return found->second;
}

std::vector<double> numbers(const std::string& text, const std::string& field, const std::string& path) {
  std::istringstream in(text);
  std::vector<double> out;
  std::string word;
  while (in >> word) {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0' || !std::isfinite(v)) refuse(path, field + ": expected numbers, got \"" + text + "\"");
    out.push_back(v);
  }
  return out;
}

// `space directions: (a,0,0) (0,b,0) (0,0,c)`: the spacing |a|, |b|, |c|; axis-aligned only.
std::array<double, 3> spacing_of_directions(const std::string& text, const std::string& path) {
  std::array<double, 3> spacing{};
  size_t at = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const size_t open = text.find('(', at), close = text.find(')', open);
    if (open == std::string::npos || close == std::string::npos)
      refuse(path, "space directions: expected three vectors (x,y,z), got \"" + text + "\"");
    std::string inside = text.substr(open + 1, close - open - 1);
    std::replace(inside.begin(), inside.end(), ',', ' ');
    const std::vector<double> v = numbers(inside, "space directions", path);
    if (v.size() != 3) refuse(path, "space directions: expected three components a vector, got \"" + text + "\"");
    for (int c = 0; c < 3; ++c) {
      if (c != axis && v[size_t(c)] != 0.0)
        refuse(path, "space directions: only axis-aligned volumes are read (axis " + std::to_string(axis) +
                         " must lie along its own axis), got \"" + text + "\"");
    }
    spacing[size_t(axis)] = std::abs(v[size_t(axis)]);
    at = close + 1;
  }
  return spacing;
}

template <typename T>
T byte_swapped(T value) {
  std::array<std::byte, sizeof(T)> bytes;
  std::memcpy(bytes.data(), &value, sizeof(T));
  std::reverse(bytes.begin(), bytes.end());
  std::memcpy(&value, bytes.data(), sizeof(T));
  return value;
}

template <typename T>
void append_samples(const std::vector<char>& bytes, bool swap, std::vector<float>& out) {
  out.resize(bytes.size() / sizeof(T));
  for (size_t i = 0; i < out.size(); ++i) {
    T v;
    std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
    out[i] = float(swap ? byte_swapped(v) : v);
  }
}

}  // namespace

size_t scalar_bytes(ScalarType type) {
  switch (type) {
    case ScalarType::uchar: return 1;
    case ScalarType::ushort:
    case ScalarType::short_: return 2;
    case ScalarType::float_: return 4;
  }
  return 1;
}

std::string scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::uchar: return "uchar";
    case ScalarType::ushort: return "ushort";
    case ScalarType::short_: return "short";
    case ScalarType::float_: return "float";
  }
  return "uchar";
}

ScalarType scalar_type_named(const std::string& name) {
  static const std::map<std::string, ScalarType> synonyms{
      {"uchar", ScalarType::uchar},          {"unsigned char", ScalarType::uchar},    {"uint8", ScalarType::uchar},
      {"uint8_t", ScalarType::uchar},        {"ushort", ScalarType::ushort},          {"unsigned short", ScalarType::ushort},
      {"unsigned short int", ScalarType::ushort}, {"uint16", ScalarType::ushort},     {"uint16_t", ScalarType::ushort},
      {"short", ScalarType::short_},         {"short int", ScalarType::short_},       {"signed short", ScalarType::short_},
      {"signed short int", ScalarType::short_}, {"int16", ScalarType::short_},        {"int16_t", ScalarType::short_},
      {"float", ScalarType::float_}};
  const auto found = synonyms.find(lower(trimmed(name)));
  if (found == synonyms.end()) throw VolumeFileError("type \"" + name + "\": expected uchar, ushort, short or float");
  return found->second;
}

std::array<double, 2> scalar_type_range(ScalarType type) {
  switch (type) {
    case ScalarType::uchar: return {0, 255};
    case ScalarType::ushort: return {0, 65535};
    case ScalarType::short_: return {-32768, 32767};
    case ScalarType::float_: return {0, 1};
  }
  return {0, 1};
}

VolumeLayout parse_nrrd_header(const std::string& text, const std::string& path) {
  const HeaderFields h = header_fields(text, path);
  VolumeLayout layout;
  try {
    layout.type = scalar_type_named(required(h, "type", path));
  } catch (const VolumeFileError& e) {
    refuse(path, e.what());
  }
  if (trimmed(required(h, "dimension", path)) != "3")
    refuse(path, "dimension: " + required(h, "dimension", path) + ", expected 3 (a scalar volume)");
  const std::vector<double> sizes = numbers(required(h, "sizes", path), "sizes", path);
  if (sizes.size() != 3) refuse(path, "sizes: expected three sizes, got \"" + required(h, "sizes", path) + "\"");
  for (size_t i = 0; i < 3; ++i) {
    if (sizes[i] < 1 || sizes[i] > 16384 || sizes[i] != std::floor(sizes[i]))
      refuse(path, "sizes: expected whole numbers from 1 to 16384, got \"" + required(h, "sizes", path) + "\"");
    layout.sizes[i] = uint32_t(sizes[i]);
  }
  const std::string encoding = lower(required(h, "encoding", path));
  if (encoding != "raw")
    refuse(path, "encoding: " + encoding + " is not read, expected raw (re-save the file uncompressed, e.g. `unu save -e raw`)");
  if (const auto endian = h.fields.find("endian"); endian != h.fields.end()) {
    const std::string e = lower(endian->second);
    if (e != "little" && e != "big") refuse(path, "endian: expected little or big, got \"" + endian->second + "\"");
    layout.big_endian = e == "big";
  } else if (scalar_bytes(layout.type) > 1) {
    refuse(path, "the header has no \"endian:\" field (needed for " + scalar_type_name(layout.type) + " samples)");
  }
  const auto spacings = h.fields.find("spacings"), directions = h.fields.find("space directions");
  if (spacings != h.fields.end()) {
    const std::vector<double> s = numbers(spacings->second, "spacings", path);
    if (s.size() != 3) refuse(path, "spacings: expected three numbers, got \"" + spacings->second + "\"");
    for (size_t i = 0; i < 3; ++i) layout.spacing[i] = std::abs(s[i]);
  } else if (directions != h.fields.end()) {
    layout.spacing = spacing_of_directions(directions->second, path);
  }
  for (const double s : layout.spacing) {
    if (!(s > 0)) refuse(path, "spacing: expected three spacings above 0");
  }
  for (const char* skip : {"line skip", "lineskip", "byte skip", "byteskip"}) {
    if (const auto found = h.fields.find(skip); found != h.fields.end() && trimmed(found->second) != "0")
      refuse(path, std::string(skip) + ": " + found->second + " is not read, expected 0");
  }
  const auto detached = h.fields.count("data file") ? h.fields.find("data file") : h.fields.find("datafile");
  if (detached != h.fields.end()) {
    const std::string name = detached->second;
    if (name.find('%') != std::string::npos || name.rfind("LIST", 0) == 0)
      refuse(path, "data file: \"" + name + "\": only one data file is read (no lists or patterns)");
    layout.data_file = (std::filesystem::path(path).parent_path() / name).lexically_normal().string();
    layout.data_offset = 0;
  } else {
    if (h.data_offset == 0) refuse(path, "the header ends without a blank line before the data (and names no data file)");
    layout.data_file = path;
    layout.data_offset = h.data_offset;
  }
  return layout;
}

VolumeLayout read_nrrd_layout(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) refuse(path, "cannot open the file");
  std::string text, line;
  while (std::getline(in, line)) {
    text += line + "\n";
    if (trimmed(line).empty() || text.size() > (1u << 20)) break;
  }
  return parse_nrrd_header(text, path);
}

std::vector<float> read_samples(const VolumeLayout& layout) {
  const uint64_t count = uint64_t(layout.sizes[0]) * layout.sizes[1] * layout.sizes[2];
  const uint64_t bytes = count * scalar_bytes(layout.type);
  std::error_code error;
  const uint64_t file_size = std::filesystem::file_size(layout.data_file, error);
  if (error) refuse(layout.data_file, "cannot read the data file (" + error.message() + ")");
  const uint64_t held = file_size >= layout.data_offset ? file_size - layout.data_offset : 0;
  if (held != bytes) {
    refuse(layout.data_file, "holds " + std::to_string(held) + " bytes of samples, expected " + std::to_string(bytes) + " (" +
                                 std::to_string(layout.sizes[0]) + " × " + std::to_string(layout.sizes[1]) + " × " +
                                 std::to_string(layout.sizes[2]) + " " + scalar_type_name(layout.type) + ")");
  }
  std::ifstream in(layout.data_file, std::ios::binary);
  std::vector<char> raw(bytes);
  in.seekg(std::streamoff(layout.data_offset));
  if (!in.read(raw.data(), std::streamsize(bytes))) refuse(layout.data_file, "cannot read the samples");
  const bool swap = layout.big_endian != (std::endian::native == std::endian::big);
  std::vector<float> out;
  switch (layout.type) {
    case ScalarType::uchar: append_samples<uint8_t>(raw, false, out); break;
    case ScalarType::ushort: append_samples<uint16_t>(raw, swap, out); break;
    case ScalarType::short_: append_samples<int16_t>(raw, swap, out); break;
    case ScalarType::float_: append_samples<float>(raw, swap, out); break;
  }
  return out;
}

std::vector<float> normalised(const std::vector<float>& samples, std::array<double, 2> window) {
  std::vector<float> out(samples.size());
  const double width = window[1] - window[0];
  for (size_t i = 0; i < samples.size(); ++i) {
    const double v = width > 0 ? (double(samples[i]) - window[0]) / width : 0.0;
    out[i] = float(std::clamp(std::isnan(v) ? 0.0 : v, 0.0, 1.0));
  }
  return out;
}

std::array<double, 3> box_proportions(const VolumeLayout& layout) {
  std::array<double, 3> side{};
  for (size_t i = 0; i < 3; ++i) side[i] = double(layout.sizes[i]) * layout.spacing[i];
  const double longest = std::max({side[0], side[1], side[2]});
  for (double& s : side) s /= longest;
  return side;
}

VolumeLayout volume_layout(const VolumeData& volume) {
  if (!volume.raw) return read_nrrd_layout(volume.file);
  VolumeLayout layout;
  layout.type = scalar_type_named(volume.raw_type);
  for (size_t i = 0; i < 3; ++i) layout.sizes[i] = uint32_t(volume.raw_sizes[i]);
  layout.spacing = volume.raw_spacing;
  layout.big_endian = volume.raw_big_endian;
  layout.data_file = volume.file;
  return layout;
}

std::array<double, 2> volume_window(const VolumeData& volume, const VolumeLayout& layout) {
  return volume.window ? *volume.window : scalar_type_range(layout.type);
}

}  // namespace volgraph::volume_file
