// cloud_weather_map: the scene's weather map (scene.clouds.weather_map, Schneider & Vos
// 2015) as a texture: r the coverage multiplier, g the cloud type, a 1 where g is the type
// (a colour image) and 0 where the layer's type holds (a grey one); the image resampled to
// `size` × `size` (passes/clouds/cloud_weather_map.h, the texels the CPU reference holds too).
// Made once and cached (the image, the layer and the size alone); cloud_march and
// cloud_shadow_map read it through their optional `weather` input. No shader: an upload.
#include <span>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/clouds/cloud_weather_map.h"
#include "passes/plumbing/staged_upload.h"
#include "passes/register_pass.h"

namespace volgraph {
namespace {

std::vector<ParamProblem> weather_map_problems(const PassDecl& decl, const Scene& scene, const std::vector<ParamValue>& params);

struct CloudWeatherMapTable : PassTable {
  CloudWeatherMapTable()
      : PassTable("cloud_weather_map", PassKind::transfer,
                  "The cloud layer's weather map (scene.clouds.weather_map) as a texture: r coverage, g cloud type.") {
    decl.needs = feature_bit(SceneFeature::clouds);
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::clouds);
    decl.check_scene = weather_map_problems;
  }
  // Variants.
  VariantHandle image = variant("image", "the scene's weather_map image, resampled bilinearly with repeat to size × size");
  // Parameters.
  ParamHandle<int64_t> size = integer("size", 128, 1, 4096, "texels", "the texture's side (the image's own when equal: no resampling)");
  // Slots.
  SlotHandle weather = output("weather", ResourceKind::texture2d, Usage::copy_dst, Format::rgba8_unorm, SizeSpec::square_of(size),
                              "r the coverage multiplier, g the cloud type, a 1 where g is the type (0: the layer's type)");
};

// The scene must give a weather map, and its file must be an image (bad input: one
// message at scene.clouds.weather_map/image).
std::vector<ParamProblem> weather_map_problems(const PassDecl&, const Scene& scene, const std::vector<ParamValue>&) {
  const CloudLayer& layer = *scene.clouds;
  if (!layer.weather_map) {
    return {{"", "cloud_weather_map needs scene.clouds.weather_map (an image, the metres it spans, an offset)", layer.where}};
  }
  const CloudWeatherMap& map = *layer.weather_map;
  const std::string problem = plumbing::image_file_problem(map.image);
  if (problem.empty()) return {};
  Where where = map.where;
  where.pointer += "/image";
  return {{"", map.image + ": " + problem, where}};
}

class CloudWeatherMapExecution final : public PassExecution {
 public:
  explicit CloudWeatherMapExecution(const CloudWeatherMapTable& table) : t_(table) {}

  // Runs when the cache key changed: the first frame, another layer or image path, another size.
  void record(PassContext& c) override {
    const plumbing::Rgba8Image image = plumbing::read_image_file(c.scene->clouds->weather_map->image);
    const std::vector<uint8_t> texels = clouds::weather_texels(image, uint32_t(c.param(t_.size)));
    upload_.record(c, std::as_bytes(std::span(texels)), c.texture(t_.weather));
  }

 private:
  const CloudWeatherMapTable& t_;
  plumbing::StagedUpload upload_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CloudWeatherMapTable, CloudWeatherMapExecution);

}  // namespace volgraph
