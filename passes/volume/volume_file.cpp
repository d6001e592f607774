// volume_file: the scene's volume file (scene.volume_data: a NRRD file or a .raw file with its
// layout; RTR4 14.3.1) as the scalar 3D texture volume_phantom makes: `density`, r the
// samples mapped to [0, 1] through the window (the config's, else the sample type's range),
// x the file's fastest axis. rgba16float as the phantom's (g b a zero): filterable on both
// backends, and its rows are whole 4-byte words whatever the width, as WebGPU's copies need
// (r16float rows of an odd width are not); a half float is within 2⁻¹¹ relative. Its size is the params `width`,
// `height`, `depth`, which must equal the file's (the graph sizes resources before any file
// is read; the scene check says what the file holds). Read once and cached: the file's path,
// size and time of change are in the key (ScenePart::volume_data). volume_visualize's
// `box: volume_data` gives its box the proportions of sizes × spacing. No shader: an upload.
// Reader: passes/volume/volume_file_reader.h.
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/packing.hpp>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/staged_upload.h"
#include "passes/register_pass.h"
#include "passes/volume/volume_file_reader.h"

namespace volgraph {
namespace {

std::vector<ParamProblem> volume_file_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params);

struct VolumeFileTable : PassTable {
  VolumeFileTable()
      : PassTable("volume_file", PassKind::transfer,
                  "The scene's volume file (scene.volume_data: NRRD or raw) as a scalar 3D texture for volume_visualize.") {
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::volume_data);
    decl.check_scene = volume_file_problems;
  }
  // Variants.
  VariantHandle samples = variant("samples", "the file's samples, one texel each, mapped to [0, 1] through the window");
  // Parameters.
  ParamHandle<int64_t> width = integer("width", 64, 1, 16384, "texels", "the file's samples along x (must equal the file's)");
  ParamHandle<int64_t> height = integer("height", 64, 1, 16384, "texels", "the file's samples along y (must equal the file's)");
  ParamHandle<int64_t> depth = integer("depth", 64, 1, 16384, "texels", "the file's samples along z (must equal the file's)");
  // Slots.
  SlotHandle density = output("density", ResourceKind::texture3d, Usage::copy_dst, Format::rgba16_float, SizeSpec::volume_of(width, height, depth),
                              "r the sample mapped to [0, 1] (g b a zero); texel (i, j, k) the file's sample i + w·(j + h·k)");
};

// The scene must name a volume file whose header reads, whose data holds sizes × the
// type's bytes, and whose sizes equal the params (one message at scene.volume_data/file,
// or at the param).
std::vector<ParamProblem> volume_file_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params) {
  if (!scene.volume_data) return {{"", "volume_file needs scene.volume_data (a NRRD or .raw file: {\"file\": …})"}};
  const VolumeData& volume = *scene.volume_data;
  Where where = volume.where;
  where.pointer += "/file";
  volume_file::VolumeLayout layout;
  try {
    layout = volume_file::volume_layout(volume);
    volume_file::read_samples(layout);
  } catch (const volume_file::VolumeFileError& e) {
    return {{"", e.what(), where}};
  }
  static const VolumeFileTable t;
  const std::array<ParamHandle<int64_t>, 3> sides{t.width, t.height, t.depth};
  std::vector<ParamProblem> problems;
  for (size_t i = 0; i < 3; ++i) {
    const int64_t asked = param_in(params, sides[i]);
    if (asked != int64_t(layout.sizes[i])) {
      problems.push_back({param_name(decl, sides[i]), volume.file + " holds " + std::to_string(layout.sizes[0]) + " × " +
                                                          std::to_string(layout.sizes[1]) + " × " + std::to_string(layout.sizes[2]) +
                                                          " samples: expected " + std::to_string(layout.sizes[i]) + ", got " + std::to_string(asked)});
    }
  }
  return problems;
}

class VolumeFileExecution final : public PassExecution {
 public:
  explicit VolumeFileExecution(const VolumeFileTable& table) : t_(table) {}

  // Runs when the cache key changed: the first frame, another file (or the file rewritten), window or size.
  void record(PassContext& c) override {
    const VolumeData& volume = *c.scene->volume_data;
    const volume_file::VolumeLayout layout = volume_file::volume_layout(volume);
    const std::vector<float> values = volume_file::normalised(volume_file::read_samples(layout), volume_file::volume_window(volume, layout));
    std::vector<uint16_t> texels(values.size() * 4, 0);  // r the value, g b a zero
    for (size_t i = 0; i < values.size(); ++i) texels[4 * i] = glm::packHalf1x16(values[i]);
    upload_.record(c, std::as_bytes(std::span(texels)), c.texture(t_.density));
  }

 private:
  const VolumeFileTable& t_;
  plumbing::StagedUpload upload_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VolumeFileTable, VolumeFileExecution);

}  // namespace volgraph
