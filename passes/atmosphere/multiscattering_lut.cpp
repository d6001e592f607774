// atmosphere_multiscattering_lut (Hillaire 2020 §5.5): Ψ_ms, the contribution of every
// scattering order past the first for a sun of unit illuminance, taken as isotropic and
// independent of the view, by altitude (v) and the sun's zenith cosine (u), both linear
// (physics/atmosphere_lut.h). Each texel integrates L_2nd and f_ms over `directions`²
// directions uniform on the sphere, `steps` steps a ray, reading the sun's transmittance
// from the transmittance LUT (physics/atmosphere_multiscattering.h has the equations and
// the CPU twin). The sky and the aerial perspective add σs · Ψ_ms · E at each sample.
// 32 × 32 rgba16f as Hillaire 2020 (filtered when read). Cached with the atmosphere.
// Shader: shaders/atmosphere_multiscattering_lut.comp.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "physics/atmosphere.h"
#include "shaders/bindings/atmosphere_multiscattering_lut.comp.h"

namespace volgraph {
namespace {

namespace atmosphere_multiscattering_lut_shader = shaders::atmosphere_multiscattering_lut_comp;

struct MultiscatteringLutTable : PassTable {
  MultiscatteringLutTable()
      : PassTable("atmosphere_multiscattering_lut", PassKind::compute,
                  "Hillaire 2020's isotropic multiple-scattering term Ψ_ms by altitude and sun zenith cosine.") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::atmosphere);
  }
  // Variants.
  VariantHandle hillaire = variant("hillaire", "second order over a sphere of directions, 1/(1 − f_ms) for the rest (Hillaire 2020 eq. 5–10)");
  // Parameters.
  ParamHandle<int64_t> width = integer("width", 32, 2, 1024, "texels", "sun zenith cosines");
  ParamHandle<int64_t> height = integer("height", 32, 2, 1024, "texels", "altitudes");
  ParamHandle<int64_t> directions = integer("directions", 8, 1, 64, "", "directions per axis (their square in all: 64)");
  ParamHandle<int64_t> steps = integer("steps", 20, 1, 512, "", "steps along each direction");
  // Slots.
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled,
                                   "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle multiscattering = output("multiscattering", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                      SizeSpec::rect_of(width, height), "Ψ_ms rgb for a sun of unit illuminance",
                                      {.format_overridable = true});
};

class MultiscatteringLutExecution final : public PassExecution {
 public:
  explicit MultiscatteringLutExecution(const MultiscatteringLutTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "atmosphere_multiscattering_lut.comp");
    atmosphere_.setup(s, program_);
    const gpu::MultiscatteringLutParams params{{int32_t(s.param(t_.directions)), int32_t(s.param(t_.steps)), 0, 0}};
    params_ = plumbing::create_shared_uniform_block(s.device, program_, atmosphere_multiscattering_lut_shader::params, s.name() + " params", params);
  }

  void record(PassContext& c) override {
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp);
    const rhi::BindGroupId group =
        c.bind_group(program_, {bind(atmosphere_multiscattering_lut_shader::atmosphere, atmosphere_.write(c)), bind(atmosphere_multiscattering_lut_shader::params, params_),
                                bind(atmosphere_multiscattering_lut_shader::transmittance, c.view(t_.transmittance)), bind(atmosphere_multiscattering_lut_shader::nearest, nearest),
                                bind(atmosphere_multiscattering_lut_shader::multiscattering_lut, c.view(t_.multiscattering))});
    const Extent size = c.extent(t_.multiscattering);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, {size.width, size.height, 1});
  }

 private:
  const MultiscatteringLutTable& t_;
  plumbing::ComputeProgram program_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(MultiscatteringLutTable, MultiscatteringLutExecution);

}  // namespace volgraph
