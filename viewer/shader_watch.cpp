#include "viewer/shader_watch.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace volgraph::viewer {
namespace {

bool is_shader(const std::filesystem::path& p) {
  const std::string e = p.extension().string();
  return e == ".comp" || e == ".vert" || e == ".frag";
}

bool is_source(const std::filesystem::path& p) {
  const std::string e = p.extension().string();
  return is_shader(p) || e == ".glsl" || e == ".h";
}

std::string source_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A shell word: the path single-quoted.
std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

ShaderWatch::ShaderWatch(std::filesystem::path folder, std::string compiler) : folder_(std::move(folder)), compiler_(std::move(compiler)) {
  std::error_code ec;
  if (folder_.empty() || !std::filesystem::is_directory(folder_, ec)) return;
  stamps_ = stamp();
}

std::map<std::filesystem::path, std::filesystem::file_time_type> ShaderWatch::stamp() const {
  std::map<std::filesystem::path, std::filesystem::file_time_type> out;
  std::error_code ec;
  for (const auto& dir : {folder_, folder_ / "include"}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      if (entry.is_regular_file(ec) && is_source(entry.path())) out[entry.path()] = entry.last_write_time(ec);
    }
  }
  return out;
}

// The files `file` includes (#include "x": beside it, then in the folder and its include/).
std::vector<std::filesystem::path> ShaderWatch::includes_of(const std::filesystem::path& file) const {
  static const std::regex include_line(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<std::filesystem::path> out;
  std::istringstream text(source_text(file));
  std::string line;
  std::smatch m;
  while (std::getline(text, line)) {
    if (!std::regex_search(line, m, include_line)) continue;
    for (const auto& base : {file.parent_path(), folder_, folder_ / "include"}) {
      const std::filesystem::path candidate = (base / m[1].str()).lexically_normal();
      if (stamps_.count(candidate)) {
        out.push_back(candidate);
        break;
      }
    }
  }
  return out;
}

// The shaders that are, or include (transitively), one of `changed`.
std::vector<std::string> ShaderWatch::affected(const std::vector<std::filesystem::path>& changed) const {
  const std::set<std::filesystem::path> dirty(changed.begin(), changed.end());
  std::vector<std::string> out;
  for (const auto& [file, time] : stamps_) {
    if (!is_shader(file) || file.parent_path() != folder_) continue;
    std::set<std::filesystem::path> seen{file};
    std::vector<std::filesystem::path> todo{file};
    bool hit = false;
    while (!todo.empty() && !hit) {
      const std::filesystem::path next = todo.back();
      todo.pop_back();
      hit = dirty.count(next) > 0;
      for (const auto& inc : includes_of(next)) {
        if (seen.insert(inc).second) todo.push_back(inc);
      }
    }
    if (hit) out.push_back(file.filename().string());
  }
  return out;
}

// glslangValidator as shaders/CMakeLists.txt runs it; its first message on failure.
bool ShaderWatch::compile(const std::string& shader, ShaderChanges& out) const {
  const std::filesystem::path spirv = std::filesystem::temp_directory_path() / ("volgraph_view_" + std::to_string(::getpid()) + "_" + shader + ".spv");
  const std::filesystem::path log = spirv.string() + ".log";
  const std::string command = shell_quoted(compiler_) + " --quiet --target-env vulkan1.1 -I" + shell_quoted(folder_.string()) + " -o " +
                              shell_quoted(spirv.string()) + " " + shell_quoted((folder_ / shader).string()) + " >" + shell_quoted(log.string()) + " 2>&1";
  const int status = std::system(command.c_str());
  const std::string messages = source_text(log);
  std::filesystem::remove(log);
  if (status != 0 || !std::filesystem::exists(spirv)) {
    const std::string first = messages.substr(0, messages.find('\n', messages.find("ERROR")));
    out.error = "view: shader " + (folder_ / shader).string() + " does not compile; the last good one runs on:\n" + first;
    std::filesystem::remove(spirv);
    return false;
  }
  const std::string bytes = source_text(spirv);
  std::filesystem::remove(spirv);
  CompiledShader compiled{shader, std::vector<uint32_t>(bytes.size() / 4)};
  std::copy(bytes.begin(), bytes.begin() + compiled.spirv.size() * 4, reinterpret_cast<char*>(compiled.spirv.data()));
  out.compiled.push_back(std::move(compiled));
  return true;
}

ShaderChanges ShaderWatch::poll() {
  ShaderChanges out;
  if (!active()) return out;
  const auto now = stamp();
  std::vector<std::filesystem::path> changed;
  for (const auto& [file, time] : now) {
    const auto it = stamps_.find(file);
    if (it == stamps_.end() || it->second != time) changed.push_back(file);
  }
  stamps_ = now;
  if (changed.empty()) return out;
  for (const std::string& shader : affected(changed)) {
    if (!compile(shader, out)) break;
  }
  return out;
}

}  // namespace volgraph::viewer
