// cloud_noise: the three tileable noise textures of Schneider & Vos 2015's clouds, made
// once by the graph and cached: `shape` (128³: r Perlin-Worley, g b a Worley sums at
// increasing frequencies — the base shape), `detail` (32³: Worley sums that erode the
// edges) and `curl` (128²: 2D curl noise that distorts the detail). Each texel is
// shaders/include/cloud_noise.h, the text the CPU twin (physics/cloud_noise.h) compiles too.
// The textures depend on the seed and sizes alone: cached, never recomputed while they hold.
// Shaders: shaders/cloud_noise_shape.comp, cloud_noise_detail.comp, cloud_noise_curl.comp.
#include <array>
#include <cstddef>
#include <cstdint>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "shaders/bindings/cloud_noise_curl.comp.h"
#include "shaders/bindings/cloud_noise_detail.comp.h"
#include "shaders/bindings/cloud_noise_shape.comp.h"

namespace volgraph {
namespace {

namespace cloud_noise_shape_shader = shaders::cloud_noise_shape_comp;
namespace cloud_noise_detail_shader = shaders::cloud_noise_detail_comp;
namespace cloud_noise_curl_shader = shaders::cloud_noise_curl_comp;

struct CloudNoiseTable : PassTable {
  CloudNoiseTable()
      : PassTable("cloud_noise", PassKind::compute,
                  "Tileable cloud noise textures (Schneider & Vos 2015): base shape, erosion detail, curl distortion.") {
    decl.needs = feature_bit(SceneFeature::clouds);
    decl.cached = true;
    decl.frame_invariant = true;
  }
  // Variants.
  VariantHandle schneider_vos = variant("schneider_vos", "Perlin-Worley and Worley octaves (Schneider & Vos 2015)");
  // Parameters.
  ParamHandle<int64_t> shape_size = integer("shape_size", 128, 8, 512, "texels", "the shape texture's side (a cube)");
  ParamHandle<int64_t> detail_size = integer("detail_size", 32, 8, 256, "texels", "the detail texture's side (a cube)");
  ParamHandle<int64_t> curl_size = integer("curl_size", 128, 8, 1024, "texels", "the curl texture's side (a square)");
  ParamHandle<int64_t> seed = integer("seed", 0, 0, 65535, "", "the hash's seed: another seed, other clouds");
  // Slots.
  SlotHandle shape = output("shape", ResourceKind::texture3d, Usage::storage_write, Format::rgba8_unorm,
                            SizeSpec::square_layers_of(shape_size, shape_size),
                            "r Perlin-Worley, g b a Worley sums at periods 4, 8, 16 (tileable)");
  SlotHandle detail = output("detail", ResourceKind::texture3d, Usage::storage_write, Format::rgba8_unorm,
                             SizeSpec::square_layers_of(detail_size, detail_size), "r g b Worley sums at periods 2, 4, 8 (tileable)");
  SlotHandle curl = output("curl", ResourceKind::texture2d, Usage::storage_write, Format::rgba8_unorm, SizeSpec::square_of(curl_size),
                           "r g: the curl of a gradient-noise potential, 0.5 + 0.5 · curl / 8 (tileable)");
};

class CloudNoiseExecution final : public PassExecution {
 public:
  explicit CloudNoiseExecution(const CloudNoiseTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    shape_ = plumbing::create_compute_program(s.device, "cloud_noise_shape.comp");
    detail_ = plumbing::create_compute_program(s.device, "cloud_noise_detail.comp");
    curl_ = plumbing::create_compute_program(s.device, "cloud_noise_curl.comp");
    const gpu::CloudNoiseParams params{{uint32_t(s.param(t_.seed)), 0, 0, 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, shape_, cloud_noise_shape_shader::params, s.name() + " params", params);
  }

  // Runs when the cache key changed: the first frame, or another seed or size.
  void record(PassContext& c) override {
    fill(c, shape_, cloud_noise_shape_shader::params, cloud_noise_shape_shader::shape, t_.shape);
    fill(c, detail_, cloud_noise_detail_shader::params, cloud_noise_detail_shader::detail, t_.detail);
    fill(c, curl_, cloud_noise_curl_shader::params, cloud_noise_curl_shader::curl, t_.curl);
  }

 private:
  // One texture by its program: `params` and `image` are that shader's variables.
  void fill(PassContext& c, const plumbing::ComputeProgram& program, rhi::ShaderBinding params, rhi::ShaderBinding image, SlotHandle texture) {
    const rhi::BindGroupId group = c.bind_group(program, {bind(params, params_), bind(image, c.view(texture))});
    plumbing::dispatch(c.encoder, c.name(), program, {group}, c.extent(texture));
  }

  const CloudNoiseTable& t_;
  plumbing::ComputeProgram shape_, detail_, curl_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CloudNoiseTable, CloudNoiseExecution);

}  // namespace volgraph
