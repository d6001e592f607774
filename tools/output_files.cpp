#include "tools/output_files.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "graph/diagnostics.h"

namespace volgraph {
namespace {

std::string system_reason() { return std::strerror(errno); }

// A temporary name for `target` in its folder, unique to this process and stage
// ("NAME.tmp-PID-INDEX.EXT": readers that skip ".tmp-" names rely on the tag and the
// extension), no longer than a name the folder takes (NAME_MAX, 255 where not said):
// a target's name near that limit is cut to leave room for the tag, so that any name the
// filesystem accepts can be staged.
std::string temporary_name(const std::filesystem::path& target, size_t index) {
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  const long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  const size_t name_max = limit > 0 ? size_t(limit) : 255;
  const std::string extension = target.extension().string();
  const std::string tag =
      ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(index) + (extension.size() <= 32 ? extension : "");
  std::string name = target.filename().string();
  if (name.size() + tag.size() > name_max) name.resize(name_max > tag.size() ? name_max - tag.size() : 0);
  return (target.parent_path() / (name + tag)).string();
}

}  // namespace

void write_file_checked(const std::string& path, std::span<const std::byte> bytes, const std::string& name) {
  const std::string named = name.empty() ? path : name;
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw IoError(named + ": " + system_reason());
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const bool flushed = written && std::fflush(f) == 0;
  const std::string reason = flushed ? "" : system_reason();
  const bool closed = std::fclose(f) == 0;
  if (!flushed) throw IoError(named + ": " + reason);
  if (!closed) throw IoError(named + ": " + system_reason());
}

void check_output_target(const std::string& path, const std::string& flag) {
  auto fail = [&](const std::string& message) { throw ConfigError({{{"<command line>", flag + " " + path, 0}, message}}); };
  const std::filesystem::path target(path);
  std::error_code ec;
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  if (!std::filesystem::is_directory(folder, ec)) fail("folder " + folder.string() + " does not exist");
  if (std::filesystem::is_directory(target, ec)) fail("is a directory; expected a file name");
  if (std::filesystem::exists(target, ec) && !std::filesystem::is_regular_file(target, ec)) {
    fail("is not a regular file (a FIFO or device); expected a file name");
  }
}

std::string canonical_path_text(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  return ec ? std::filesystem::path(path).lexically_normal().string() : canonical.string();
}

void check_outputs_not_inputs(const std::vector<NamedInput>& inputs, const std::string& flag, const std::string& dir,
                              const std::vector<std::string>& names, const std::vector<std::string>& folders) {
  const std::filesystem::path out(canonical_path_text(dir));
  for (const NamedInput& input : inputs) {
    if (input.path.empty() || input.path == "cpu") continue;
    const std::filesystem::path in(canonical_path_text(input.path));
    std::string clash;
    for (const std::string& name : names) {
      if (in == out / name) clash = (std::filesystem::path(dir) / name).string();
    }
    for (const std::string& folder : folders) {
      if (in.parent_path() == out / folder) clash = (std::filesystem::path(dir) / folder).string() + "/";
    }
    if (clash.empty()) continue;
    throw ConfigError({{{"<command line>", flag + " " + dir, 0},
                        "would overwrite " + input.what + " " + input.path + " (it is the output " + clash +
                            "); expected an output folder whose outputs are not inputs"}});
  }
}

OutputFiles::~OutputFiles() {
  std::error_code ec;
  for (const Staged& s : staged_) std::filesystem::remove(s.temporary, ec);
}

void OutputFiles::stage(const std::string& path, const std::string& flag, std::span<const std::byte> bytes) {
  check_output_target(path, flag);
  const std::string temporary = temporary_name(std::filesystem::path(path), staged_.size());
  staged_.push_back({temporary, path});
  write_file_checked(temporary, bytes, path);
}

void OutputFiles::commit() {
  for (size_t i = 0; i < staged_.size(); ++i) {
    if (std::rename(staged_[i].temporary.c_str(), staged_[i].target.c_str()) != 0) {
      throw IoError(staged_[i].target + ": " + system_reason());
    }
    staged_[i].temporary.clear();
  }
  staged_.clear();
}

}  // namespace volgraph
