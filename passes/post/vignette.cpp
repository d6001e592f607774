// vignette: a pinhole camera's natural vignetting — irradiance falls as cos⁴θ off the
// optical axis (θ between a pixel's ray and the view direction) — mixed in by `strength`.
// The example pass of the README's pass author's guide. Shader: shaders/vignette.comp.
#include <array>
#include <cmath>
#include <cstddef>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "shaders/bindings/vignette.comp.h"  // with vignette_params.h and its layout checks

namespace volgraph {
namespace {

namespace vignette_shader = shaders::vignette_comp;

struct VignetteTable : PassTable {
  VignetteTable() : PassTable("vignette", PassKind::compute, "Natural vignetting: the colour × cos⁴θ off the axis.") {}
  VariantHandle cos4 = variant("cos4", "the cos⁴ law of a pinhole camera");
  ParamHandle<double> strength = number("strength", 1, 0, 1, "", "0: no vignetting, 1: the full cos⁴θ");
  SlotHandle color = input("color", ResourceKind::texture2d, Usage::sampled, "linear radiance");
  SlotHandle vignetted = output_like("vignetted", color, Usage::storage_write, "the radiance × mix(1, cos⁴θ, strength)");
};

class VignetteExecution final : public PassExecution {
 public:
  explicit VignetteExecution(const VignetteTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "vignette.comp");
    const Extent frame = s.frame_size();
    const gpu::VignetteParams params{{float(std::tan(s.scene->camera.fov_y_deg * M_PI / 360.0)),
                                      float(double(frame.width) / double(frame.height)), float(s.param(t_.strength)), 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, vignette_shader::params, s.name() + " params", params);
  }

  void record(PassContext& c) override {
    namespace shader = vignette_shader;
    const rhi::BindGroupId group = c.bind_group(program_, {bind(shader::color, c.view(t_.color)), bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                                                           bind(shader::vignetted, c.view(t_.vignetted)), bind(shader::params, params_)});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.vignetted));
  }

 private:
  const VignetteTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(VignetteTable, VignetteExecution);

}  // namespace volgraph
