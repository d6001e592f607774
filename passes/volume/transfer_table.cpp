// transfer_table: the scene's 2D transfer table (scene.volume_data.transfer_2d, an RGBA image;
// Kniss, Kindlmann & Hansen 2002) as a texture for volume_visualize's optional `transfer_table`
// input: density along x (column i at i/(W − 1)), gradient magnitude up the image (its bottom
// row |∇ρ| = 0, its top volume_visualize's `gradient_max`), colour and opacity per texel.
// Texture row j is the image's row H − 1 − j (so row j is at j/(H − 1)·gradient_max, as
// shaders/include/volume_transfer.h's volume_transfer_table_position places it); rgba8unorm,
// the image's bytes unchanged. Its size is the params `width`, `height`, which must equal the
// image's (the graph sizes resources before any file is read). Read once and cached (the
// image's path and time of change are in ScenePart::volume_data). No shader: an upload.
#include <span>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/textures.h"
#include "passes/plumbing/staged_upload.h"
#include "passes/register_pass.h"

namespace volgraph {
namespace {

std::vector<ParamProblem> transfer_table_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params);

struct TransferTableTable : PassTable {
  TransferTableTable()
      : PassTable("transfer_table", PassKind::transfer,
                  "The scene's 2D transfer table (density × gradient magnitude, an RGBA image) for volume_visualize.") {
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::volume_data);
    decl.check_scene = transfer_table_problems;
  }
  // Variants.
  VariantHandle image = variant("image", "scene.volume_data.transfer_2d's texels: density along x, gradient magnitude up");
  // Parameters.
  ParamHandle<int64_t> width = integer("width", 256, 2, 4096, "texels", "the table's densities (the image's width; must equal it)");
  ParamHandle<int64_t> height = integer("height", 64, 1, 4096, "texels", "the table's gradient magnitudes (the image's height; must equal it)");
  // Slots.
  SlotHandle table = output("table", ResourceKind::texture2d, Usage::copy_dst, Format::rgba8_unorm, SizeSpec::rect_of(width, height),
                            "texel (i, j): colour and opacity at density i/(W − 1), |∇ρ| j/(H − 1)·gradient_max (row 0 the image's bottom)");
};

// The scene must give a table image that decodes, of the params' size (one message at
// scene.volume_data/transfer_2d, or at the param).
std::vector<ParamProblem> transfer_table_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params) {
  if (!scene.volume_data || scene.volume_data->transfer_2d.empty())
    return {{"", "transfer_table needs scene.volume_data.transfer_2d (an RGBA image: density along x, gradient magnitude up)"}};
  const std::string& path = scene.volume_data->transfer_2d;
  Where where = scene.volume_data->where;
  where.pointer += "/transfer_2d";
  if (const std::string problem = plumbing::image_file_problem(path); !problem.empty()) return {{"", path + ": " + problem, where}};
  static const TransferTableTable table;
  const plumbing::Rgba8Image image = plumbing::read_image_file(path);
  std::vector<ParamProblem> problems;
  for (const auto& [side, held] : {std::pair{table.width, image.width}, std::pair{table.height, image.height}}) {
    if (param_in(params, side) != int64_t(held)) {
      problems.push_back({param_name(decl, side), path + " is " + std::to_string(image.width) + " × " + std::to_string(image.height) +
                                                      ": expected " + std::to_string(held) + ", got " + std::to_string(param_in(params, side))});
    }
  }
  return problems;
}

// The image's rows bottom first (texture row j at gradient j/(H − 1)·gradient_max).
std::vector<uint8_t> rows_bottom_first(const plumbing::Rgba8Image& image) {
  std::vector<uint8_t> texels(image.texels.size());
  const size_t row = size_t(image.width) * 4;
  for (size_t j = 0; j < image.height; ++j)
    std::copy_n(image.texels.begin() + long((image.height - 1 - j) * row), row, texels.begin() + long(j * row));
  return texels;
}

class TransferTableExecution final : public PassExecution {
 public:
  explicit TransferTableExecution(const TransferTableTable& table) : t_(table) {}

  // Runs when the cache key changed: the first frame, another image (or the image rewritten), another size.
  void record(PassContext& c) override {
    const std::vector<uint8_t> texels = rows_bottom_first(plumbing::read_image_file(c.scene->volume_data->transfer_2d));
    upload_.record(c, std::as_bytes(std::span(texels)), c.texture(t_.table));
  }

 private:
  const TransferTableTable& t_;
  plumbing::StagedUpload upload_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(TransferTableTable, TransferTableExecution);

}  // namespace volgraph
