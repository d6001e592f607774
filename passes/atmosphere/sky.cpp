// sky: the atmosphere seen where the scene's camera sees no surface (depth at the far
// plane); surfaces keep the scene's colour (aerial perspective comes with its own pass).
// Each variant is its own technique with its own shader and inputs (variant_programs):
// - sky_view_lut (default, Hillaire 2020 §5.3): the sky-view LUT's radiance in the pixel's
//   direction (its latitude and azimuth from the sun around the camera) times the sun's
//   irradiance E, plus the sun's disk — radiance E / (π sin²α) within its angular radius
//   α, dimmed by the atmosphere's transmittance toward it (the transmittance LUT).
//   The ground below the horizon: its Lambertian radiance, lit by the sun through the air
//   and by the sky's ambient E·π·Ψ_ms, times the transmittance to it (the transmittance
//   LUT). A camera above the top of the atmosphere, which the LUT (made at the top) cannot
//   hold, gets the per-pixel march of `raymarch` instead, as Hillaire 2020's demo does
//   (RenderRayMarchingPS: the sky-view LUT only while viewHeight < TopRadius); the march
//   reads the multiple-scattering LUT when `multiscattering` is wired (else single
//   scattering alone). Shader: shaders/atmosphere_sky.frag.
// - raymarch (Hillaire 2020's RenderSkyRayMarching path): every pixel marches its own ray —
//   from where it enters the top for a camera in space (black space and the sun's disk
//   where it misses the atmosphere) to the top or the ground — reading the transmittance and
//   multiple-scattering LUTs along it, no sky-view LUT (physics::marched_sky_radiance):
//   the baseline the LUT is measured against. Shader: shaders/atmosphere_sky_raymarch.frag.
// - bruneton (Bruneton 2017's GetSkyRadiance): the sky from the precomputed scattering table
//   (atmosphere_bruneton_tables), a camera in space entering the atmosphere first, the
//   sun's disk as above and the ground lit by the sun and the table's sky irradiance
//   (GetSunAndSkyIrradiance). Shader: shaders/atmosphere_sky_bruneton.frag.
// The sun's disk may be limb-darkened (Hillaire 2016 / Neckel & Labs 1994, normalised so
// that its irradiance stays E; off by default: Bruneton 2017 and Hillaire 2020 draw a
// uniform disk, and the uniform disk is what the exact checks test).
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/register_pass.h"
#include "passes/atmosphere/bruneton_uniforms.h"
#include "passes/atmosphere/sky_pass_frame.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "shaders/bindings/atmosphere_sky.frag.h"
#include "shaders/bindings/atmosphere_sky_bruneton.frag.h"
#include "shaders/bindings/atmosphere_sky_raymarch.frag.h"

namespace volgraph {
namespace {

namespace atmosphere_sky_shader = shaders::atmosphere_sky_frag;
namespace atmosphere_sky_raymarch_shader = shaders::atmosphere_sky_raymarch_frag;
namespace atmosphere_sky_bruneton_shader = shaders::atmosphere_sky_bruneton_frag;

struct SkyTable : PassTable {
  SkyTable() : PassTable("sky", PassKind::graphics, "The atmosphere's sky and sun disk behind the scene's surfaces.") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
  }
  // Variants: the technique (the first is the default); its optional inputs name it (required_in).
  VariantHandle sky_view_lut =
      variant("sky_view_lut", "the sky from the sky-view LUT (bilinear), the sun disk through the transmittance LUT (Hillaire 2020)");
  VariantHandle raymarch = variant("raymarch", "every pixel marches its own ray through the transmittance and multiple-scattering LUTs (Hillaire 2020's RenderSkyRayMarching), no sky-view LUT");
  VariantHandle bruneton = variant("bruneton", "the sky from Bruneton 2017's precomputed scattering table (GetSkyRadiance), the ground by its irradiance table");
  // Parameters.
  ParamHandle<bool> sun_disk = flag("sun_disk", true, "draw the sun's disk");
  ParamHandle<bool> limb_darkening = flag("limb_darkening", false, "darken the sun's disk toward its limb (Hillaire 2016 after Neckel & Labs 1994; its irradiance stays E)");
  ParamHandle<bool> ground = flag("ground", true, "draw the planet's Lambertian ground where a ray meets it (lit by the sun through the air and by the sky)");
  // The march's sampling (raymarch; sky_view_lut's view from space): as the sky-view LUT's.
  ParamHandle<double> min_samples = number("min_samples", 40, 1, 512, "", "samples along the shortest rays of the march (Hillaire 2020: 4)");
  ParamHandle<double> max_samples = number("max_samples", 40, 1, 512, "", "samples along the march's rays of 100 km and longer (Hillaire 2020: 14)");
  ParamHandle<double> sample_offset = number("sample_offset", 0.5, 0, 1, "", "where in its step each sample of the march sits (Hillaire 2020: 0.3)");
  ParamHandle<bool> multiscattering_term = flag("multiscattering", true, "add σs · Ψ_ms along the march and Ψ_ms to the ground's light (off: single scattering alone)");
  // Slots: every variant's common ones, then each variant's own (optional: its variant names them).
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth", {.format = Format::d32_float});
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled,
                                   "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle sky_view = optional_input("sky_view", ResourceKind::texture2d, Usage::sampled,
                                       "the sky-view LUT (atmosphere_skyview_lut.sky_view), for sky_view_lut", {.required_in = {sky_view_lut}});
  SlotHandle multiscattering = optional_input("multiscattering", ResourceKind::texture2d, Usage::sampled,
                                              "the multiple-scattering LUT (atmosphere_multiscattering_lut.multiscattering), for raymarch and sky_view_lut's view from space", {.required_in = {raymarch}});
  SlotHandle scattering = optional_input("scattering", ResourceKind::texture3d, Usage::sampled,
                                         "Bruneton 2017's scattering table (atmosphere_bruneton_tables.scattering), for bruneton", {.required_in = {bruneton}});
  SlotHandle single_mie_scattering = optional_input("single_mie_scattering", ResourceKind::texture3d, Usage::sampled,
                                                    "Bruneton 2017's single Mie table (atmosphere_bruneton_tables.single_mie_scattering), for bruneton", {.required_in = {bruneton}});
  SlotHandle irradiance = optional_input("irradiance", ResourceKind::texture2d, Usage::sampled,
                                         "Bruneton 2017's sky irradiance table (atmosphere_bruneton_tables.irradiance), for bruneton", {.required_in = {bruneton}});
  // The sky is drawn onto the scene's colour where no surface is, so without an
  // atmosphere (the pass culled) the colour passes through unchanged.
  SlotHandle sky_color = inout("color", ResourceKind::texture2d, Usage::color_attachment_load,
                               "the scene's linear radiance (scene.color); the sky drawn behind its surfaces");
};

// Every variant's shader declares the atmosphere, the frame (gpu::SkyPassFrame), the depth, a
// nearest sampler and the transmittance LUT at the same bindings (bound by
// atmosphere_sky.frag's names), and a linear sampler but bruneton; then its own inputs.

class SkyExecution final : public PassExecution {
 public:
  explicit SkyExecution(const SkyTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    rhi::RenderPipelineDesc pipeline;
    pipeline.label = s.name() + " " + shader(s);
    pipeline.colors = {{s.desc(t_.sky_color).format, rhi::BlendMode::replace}};
    program_ = plumbing::create_render_program(s.device, pipeline, "fullscreen.vert", shader(s));
    atmosphere_.setup(s, program_);
    plumbing::check_wrapped_uniform_mirror<gpu::SkyPassFrame>(program_, 0, 1, s.name() + " frame");
    frame_ = s.device.create_buffer({s.name() + " frame", sizeof(gpu::SkyPassFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    if (s.variant_is(t_.bruneton)) table_ = plumbing::create_shared_uniform_block(s.device, program_, atmosphere_sky_bruneton_shader::table, s.name() + " table", table_shape(s));
  }

  void record(PassContext& c) override {
    namespace shared = atmosphere_sky_shader;
    const gpu::SkyPassFrame frame = sky_frame(c);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    std::vector<rhi::BoundResource> entries = {
        bind(shared::atmosphere, atmosphere_.write(c)), bind(shared::frame, frame_), bind(shared::depth, c.view(t_.depth)),
        bind(shared::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(shared::transmittance, c.view(t_.transmittance))};
    for (const rhi::BoundResource& input : variant_inputs(c)) entries.push_back(input);
    rhi::RenderPassDesc pass;
    pass.label = c.name();
    pass.colors = {{c.view(t_.sky_color), rhi::LoadOp::load}};
    c.encoder.begin_render_pass(pass);
    c.encoder.set_pipeline(program_.pipeline);
    c.encoder.set_bind_group(0, c.bind_group(program_, entries));
    c.encoder.draw(3);  // fullscreen.vert's one triangle
    c.encoder.end_render_pass();
  }

 private:
  // The variant's shader.
  std::string shader(const PassSetup& s) const {
    if (s.variant_is(t_.raymarch)) return "atmosphere_sky_raymarch.frag";
    if (s.variant_is(t_.bruneton)) return "atmosphere_sky_bruneton.frag";
    return "atmosphere_sky.frag";
  }

  // The variant's own bindings: its inputs, and the linear sampler but bruneton's (it reads its
  // rgba32f tables by texelFetch, unfilterable on WebGPU), or its table's shape.
  std::vector<rhi::BoundResource> variant_inputs(PassContext& c) const {
    const rhi::SamplerId linear = c.sampler(rhi::StockSampler::linear_clamp);
    if (c.variant_is(t_.raymarch)) return {bind(atmosphere_sky_raymarch_shader::linear, linear), bind(atmosphere_sky_raymarch_shader::multiscattering, c.view(t_.multiscattering))};
    if (c.variant_is(t_.bruneton)) {
      return {bind(atmosphere_sky_bruneton_shader::scattering, c.view(t_.scattering)), bind(atmosphere_sky_bruneton_shader::single_mie_scattering, c.view(t_.single_mie_scattering)),
              bind(atmosphere_sky_bruneton_shader::irradiance, c.view(t_.irradiance)), bind(atmosphere_sky_bruneton_shader::table, table_)};
    }
    // sky_view_lut: the multiple-scattering LUT when wired, else the sky-view LUT (a filterable
    // texture as the binding wants) in its place, never read: the frame turns the term off.
    return {bind(atmosphere_sky_shader::linear, linear), bind(atmosphere_sky_shader::sky_view, c.view(t_.sky_view)),
            bind(atmosphere_sky_shader::multiscattering, c.view(has_multiscattering(c) ? t_.multiscattering : t_.sky_view))};
  }

  // bruneton: the scattering table's shape, its nu slices those of the tables pass that
  // made it (atmosphere_bruneton_tables.nu: one source, so a reader never disagrees).
  gpu::BrunetonTableParams table_shape(const PassSetup& s) const {
    const Extent e = s.extent(t_.scattering);
    return bruneton_table_shape(e.width, e.height, e.depth, s.producer_param(t_.scattering, "nu"));
  }

  bool has_multiscattering(const PassContext& c) const { return c.bound(t_.multiscattering); }

  gpu::SkyPassFrame sky_frame(const PassContext& c) const {
    const atmosphere::SkyLook look{c.param(t_.sun_disk), c.param(t_.limb_darkening), c.param(t_.ground),
                                   c.param(t_.multiscattering_term) && has_multiscattering(c), c.param(t_.min_samples),
                                   c.param(t_.max_samples), c.param(t_.sample_offset)};
    return atmosphere::sky_pass_frame(*c.scene, c.extent(t_.sky_color), look);
  }

  const SkyTable& t_;
  plumbing::RenderProgram program_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId frame_, table_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(SkyTable, SkyExecution);

}  // namespace volgraph
