// atmosphere_skyview_lut (Hillaire 2020 §5.3): the sky's radiance around the camera for a
// sun of unit illuminance, by the view's latitude (v, non-linear either side of the horizon
// so that it stays sharp) and its azimuth from the sun (u) — physics/atmosphere_lut.h — the
// single scattering of Rayleigh and Mie plus σs · Ψ_ms (the multiple-scattering LUT)
// integrated along each ray (physics/atmosphere_sky.h has the integral and its sampling —
// midpoint samples by default, where Hillaire's offset of 0.3 is first order;
// the sun's transmittance from the transmittance LUT). A sky pass reads it for every pixel
// that sees the sky, times the sun's irradiance. 192 × 216 rgba16f (Hillaire 2020: 192 × 108).
// Depends on the atmosphere, the sun and the camera's altitude: cached on those. A camera
// above the atmosphere is placed at its top here (finite, but not its view: the sky pass
// marches each pixel instead there, passes/atmosphere/sky.cpp). Shader: shaders/atmosphere_skyview_lut.comp.
#include <algorithm>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/register_pass.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "shaders/bindings/atmosphere_skyview_lut.comp.h"

namespace volgraph {
namespace {

namespace atmosphere_skyview_lut_shader = shaders::atmosphere_skyview_lut_comp;

struct SkyViewLutTable : PassTable {
  SkyViewLutTable()
      : PassTable("atmosphere_skyview_lut", PassKind::compute,
                  "Hillaire 2020's sky-view LUT: the sky's radiance around the camera by latitude and azimuth from the sun.") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::atmosphere) | part_bit(ScenePart::camera);
  }
  // Variants.
  VariantHandle hillaire = variant("hillaire", "single scattering plus Ψ_ms along each ray, quadratically spaced samples (Hillaire 2020)");
  // Parameters.
  ParamHandle<int64_t> width = integer("width", 192, 2, 4096, "texels", "azimuths from the sun");
  // 216 latitudes (Hillaire 2020: 108) and 64 midpoint samples (40 before): the sky within
  // 0.5 % of the reference's single scattering at its worst pixel, the sun 2.5° from it or the
  // horizon beside it (0.41 %; 192 × 108 at 40 samples: 1.14 %, the horizon at sunset; 0.81 %
  // beside the sun at 31°: tests/accuracy/atmosphere_sky_accuracy_test.cpp, WorstPixel).
  // The azimuths do not matter (384 wide: the same), the latitudes and the samples do.
  // Hillaire 2020's 4–14 samples at 0.3 of each step: 16 % (tests/reference/sky_sampling_test.cpp).
  ParamHandle<int64_t> height = integer("height", 216, 2, 4096, "texels", "latitudes (Hillaire 2020: 108)");
  ParamHandle<double> min_samples = number("min_samples", 64, 1, 512, "", "samples along the shortest rays (Hillaire 2020: 4)");
  ParamHandle<double> max_samples = number("max_samples", 64, 1, 512, "", "samples along rays of 100 km and longer (Hillaire 2020: 14)");
  ParamHandle<double> sample_offset = number("sample_offset", 0.5, 0, 1, "", "where in its step each sample sits: 0.5 the midpoint, second order (Hillaire 2020: 0.3, first order)");
  ParamHandle<bool> multiscattering_term = flag("multiscattering", true, "add σs · Ψ_ms (off: single scattering alone)");
  // Slots.
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled,
                                   "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle multiscattering = input("multiscattering", ResourceKind::texture2d, Usage::sampled,
                                     "the multiple-scattering LUT (atmosphere_multiscattering_lut.multiscattering)");
  SlotHandle sky_view = output("sky_view", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                               SizeSpec::rect_of(width, height), "sky radiance rgb for a sun of unit illuminance",
                               {.format_overridable = true});
};

class SkyViewLutExecution final : public PassExecution {
 public:
  explicit SkyViewLutExecution(const SkyViewLutTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "atmosphere_skyview_lut.comp");
    atmosphere_.setup(s, program_);
    plumbing::check_wrapped_uniform_mirror<gpu::SkyViewLutParams>(program_, atmosphere_skyview_lut_shader::params, s.name() + " params");
    params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::SkyViewLutParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    const atmosphere::PlanetFrame planet = atmosphere::planet_frame(*c.scene);
    const gpu::SkyViewLutParams params{{planet.planet_up[3], planet.toward_sun[3], planet.has_sun ? 1.0f : 0.0f, 0},
                                     {float(c.param(t_.min_samples)), float(c.param(t_.max_samples)), 100e3f,
                                      c.param(t_.multiscattering_term) ? 1.0f : 0.0f},
                                     {float(c.param(t_.sample_offset)), 0, 0, 0}};
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const rhi::BindGroupId group = c.bind_group(
        program_,
        {bind(atmosphere_skyview_lut_shader::atmosphere, atmosphere_.write(c)), bind(atmosphere_skyview_lut_shader::params, params_), bind(atmosphere_skyview_lut_shader::transmittance, c.view(t_.transmittance)),
         bind(atmosphere_skyview_lut_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(atmosphere_skyview_lut_shader::multiscattering, c.view(t_.multiscattering)),
         bind(atmosphere_skyview_lut_shader::linear, c.sampler(rhi::StockSampler::linear_clamp)), bind(atmosphere_skyview_lut_shader::sky_view, c.view(t_.sky_view))});
    const Extent size = c.extent(t_.sky_view);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, {size.width, size.height, 1});
  }

 private:
  const SkyViewLutTable& t_;
  plumbing::ComputeProgram program_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(SkyViewLutTable, SkyViewLutExecution);

}  // namespace volgraph
