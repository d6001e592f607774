// Small NRRD and raw volume files written by the tests themselves into a temporary folder
// (no binaries in git): a header from its fields, then the samples, attached or detached.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace volgraph::test {

// A folder of the test's own under the system's temp folder, removed with the object.
class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("volgraph_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// The bytes of `values` as the machine holds them (little-endian here), or reversed per value.
template <typename T>
std::vector<char> sample_bytes(const std::vector<T>& values, bool swap_bytes = false) {
  std::vector<char> bytes(values.size() * sizeof(T));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  if (swap_bytes) {
    for (size_t i = 0; i < values.size(); ++i) std::reverse(bytes.begin() + long(i * sizeof(T)), bytes.begin() + long((i + 1) * sizeof(T)));
  }
  return bytes;
}

inline void write_bytes(const std::string& path, const std::string& text, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

// A NRRD file: "NRRD0004", the header's lines, a blank line, the samples.
inline void write_nrrd(const std::string& path, const std::string& fields, const std::vector<char>& samples) {
  write_bytes(path, "NRRD0004\n" + fields + "\n", samples);
}

}  // namespace volgraph::test
