// atmosphere_transmittance_lut: the transmittance from every point of the atmosphere to its
// top, by altitude and view zenith cosine, in Bruneton 2017's parametrisation
// (physics/atmosphere_lut.h: x_mu the distance to the top between its extremes, x_r the
// distance to the horizon over its largest; rays that hit the ground are not stored, as in
// Bruneton 2017 and Hillaire 2020, whose LUTs share this one). Each texel integrates the
// extinction along its ray to the top by Gauss–Legendre panels (atmosphere.glsl
// optical_depth). Default 256 × 64 in rgba32f: Bruneton 2017 notes 16-bit floats show
// artefacts. The table depends on the atmosphere alone: the pass is cached.
// Shader: shaders/atmosphere_transmittance_lut.comp.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "physics/atmosphere.h"
#include "shaders/bindings/atmosphere_transmittance_lut.comp.h"

namespace volgraph {
namespace {

namespace atmosphere_transmittance_lut_shader = shaders::atmosphere_transmittance_lut_comp;

struct TransmittanceLutTable : PassTable {
  TransmittanceLutTable()
      : PassTable("atmosphere_transmittance_lut", PassKind::compute,
                  "Transmittance to the top of the atmosphere by altitude and view zenith cosine (Bruneton 2017's parametrisation).") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::atmosphere);
  }
  // Variants.
  VariantHandle quadrature = variant("quadrature", "Gauss–Legendre panels along each texel's ray to the top");
  // Parameters.
  ParamHandle<int64_t> width = integer("width", 256, 2, 4096, "texels", "view zenith cosines (x_mu)");
  ParamHandle<int64_t> height = integer("height", 64, 2, 4096, "texels", "altitudes (x_r)");
  // 32: below 1e-4 of the double-precision integral everywhere (tests/gpu/atmosphere_lut_test.cpp).
  ParamHandle<int64_t> panels = integer("panels", 32, 1, 256, "", "Gauss–Legendre panels (4 points each) along each ray");
  // Slots.
  SlotHandle transmittance = output("transmittance", ResourceKind::texture2d, Usage::storage_write, Format::rgba32_float,
                                    SizeSpec::rect_of(width, height), "e^(−τ) rgb to the top of the atmosphere",
                                    {.format_overridable = true});
};

class TransmittanceLutExecution final : public PassExecution {
 public:
  explicit TransmittanceLutExecution(const TransmittanceLutTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "atmosphere_transmittance_lut.comp");
    atmosphere_.setup(s, program_);
    const gpu::TransmittanceLutParams params{{int32_t(s.param(t_.panels)), 0, 0, 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, atmosphere_transmittance_lut_shader::params, s.name() + " params", params);
  }

  // Runs when the cache key changed: the first frame, or a new atmosphere.
  void record(PassContext& c) override {
    const rhi::BindGroupId group = c.bind_group(program_, {bind(atmosphere_transmittance_lut_shader::atmosphere, atmosphere_.write(c)), bind(atmosphere_transmittance_lut_shader::params, params_),
                                                           bind(atmosphere_transmittance_lut_shader::transmittance, c.view(t_.transmittance))});
    const Extent size = c.extent(t_.transmittance);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, {size.width, size.height, 1});
  }

 private:
  const TransmittanceLutTable& t_;
  plumbing::ComputeProgram program_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(TransmittanceLutTable, TransmittanceLutExecution);

}  // namespace volgraph
