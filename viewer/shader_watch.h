// `view`'s shader hot reload: the shader sources (a folder laid out as shaders/: the
// *.comp/*.vert/*.frag files and include/) are polled for changes; a changed shader, and
// every shader that includes a changed file (directly or through other includes), is
// compiled again with glslangValidator and the build's flags (shaders/CMakeLists.txt),
// for the loop to hand to the device (rhi::Device::replace_shader) and rebuild the graph.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace volgraph::viewer {

struct CompiledShader {
  std::string name;              // as the passes name it: "composite.frag"
  std::vector<uint32_t> spirv;
};

// The result of one poll: what compiled, or the first compiler message (file:line).
struct ShaderChanges {
  std::vector<CompiledShader> compiled;
  std::string error;  // "" when every changed shader compiled
  bool any() const { return !compiled.empty() || !error.empty(); }
};

class ShaderWatch {
 public:
  // `folder`: the shader sources; "" or a folder that does not exist: nothing is watched.
  // `compiler`: glslangValidator's path.
  ShaderWatch(std::filesystem::path folder, std::string compiler);
  bool active() const { return !stamps_.empty(); }
  const std::filesystem::path& folder() const { return folder_; }
  // Compiles what changed on disk since the last poll (nothing when nothing did).
  ShaderChanges poll();

 private:
  std::map<std::filesystem::path, std::filesystem::file_time_type> stamp() const;
  std::vector<std::string> affected(const std::vector<std::filesystem::path>& changed) const;
  std::vector<std::filesystem::path> includes_of(const std::filesystem::path& file) const;
  bool compile(const std::string& shader, ShaderChanges& out) const;

  std::filesystem::path folder_;
  std::string compiler_;
  std::map<std::filesystem::path, std::filesystem::file_time_type> stamps_;
};

}  // namespace volgraph::viewer
