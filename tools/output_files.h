// The files a command writes, all or none (DESIGN.md: no partial output): each is
// written to a temporary name in its target's folder, with every write, flush and close
// checked, and renamed into place only when every one of them was written.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace volgraph {

// An output could not be written (disk full, I/O error): not the input's fault, so
// exit 1, not 2.
struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A text's bytes, for write_file_checked and OutputFiles::stage.
inline std::span<const std::byte> text_bytes(const std::string& text) { return std::as_bytes(std::span(text.data(), text.size())); }

// Writes `bytes` to `path` (created or truncated), checking every fwrite, the fflush and
// the fclose; throws IoError "NAME: <the system's reason>" when one fails, NAME `path`
// unless given (the target a temporary stands for).
void write_file_checked(const std::string& path, std::span<const std::byte> bytes, const std::string& name = "");

// Whether `path` can take a file: its folder exists and it is not itself a folder.
// Throws ConfigError at `flag` (e.g. "-o") with what is wrong.
void check_output_target(const std::string& path, const std::string& flag);

// A file the command reads, and what it is to the user ("the spec", "--reference").
struct NamedInput {
  std::string what, path;
};
// `path` with its folders resolved (symbolic links, "..") so that two names of one file
// compare equal; the parts that do not exist yet are kept as written; "" stays "".
std::string canonical_path_text(const std::string& path);
// No output may be an input (DESIGN.md: an input overwritten is lost): throws ConfigError
// at `flag DIR` naming both when an input is one of the files `names` in DIR, or lies in
// one of the folders `folders` of DIR (e.g. points), compared as canonical paths.
void check_outputs_not_inputs(const std::vector<NamedInput>& inputs, const std::string& flag, const std::string& dir,
                              const std::vector<std::string>& names, const std::vector<std::string>& folders = {});

class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;
  ~OutputFiles();  // removes the temporaries of files never committed

  // Checks the target (check_output_target) and writes `bytes` to a temporary name
  // beside it; throws IoError when the write fails.
  void stage(const std::string& path, const std::string& flag, std::span<const std::byte> bytes);
  // Renames every staged file into place; throws IoError when one cannot be.
  void commit();

 private:
  struct Staged {
    std::string temporary, target;
  };
  std::vector<Staged> staged_;
};

}  // namespace volgraph
