// sky: the atmosphere seen where the scene's camera sees no surface (depth at the far
// plane); surfaces keep the scene's colour (aerial perspective comes with its own pass).
// Each variant is its own technique with its own shader and inputs (variant_programs):
// - sky_view_lut (default, Hillaire 2020 §5.3): the sky-view LUT's radiance in the pixel's
//   direction (its latitude and azimuth from the sun around the camera) times the sun's
//   irradiance E, plus the sun's disk — radiance E / (π sin²α) within its angular radius
//   α, dimmed by the atmosphere's transmittance toward it (the transmittance LUT).
//   Shader: shaders/atmosphere_sky.comp.
#include <array>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/atmosphere/atmosphere_passes.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"

namespace volgraph {
namespace {

struct SkyTable : PassTable {
  SkyTable() : PassTable("sky", PassKind::compute, "The atmosphere's sky and sun disk behind the scene's surfaces.") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
  }
  // Variants: the technique (the first is the default), each with the inputs it needs.
  VariantHandle sky_view_lut =
      variant("sky_view_lut", "the sky from the sky-view LUT (bilinear), the sun disk through the transmittance LUT (Hillaire 2020)", 0,
              {"sky_view"});
  // Parameters.
  ParamHandle<bool> sun_disk = flag("sun_disk", true, "draw the sun's disk");
  // Slots: every variant's common ones, then each variant's own (optional: its variant names them).
  SlotHandle surfaces = input("surfaces", ResourceKind::texture2d, Usage::sampled, "the scene's linear radiance (scene.color)");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth", {.format = Format::d32_float});
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled,
                                   "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle sky_view = optional_input("sky_view", ResourceKind::texture2d, Usage::sampled,
                                       "the sky-view LUT (atmosphere_skyview_lut.sky_view), for sky_view_lut");
  SlotHandle sky_color = output("color", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                                "the scene's radiance with the sky behind it", {.size_overridable = true});
};

// The bindings every variant's shader shares (set 0): 0 the atmosphere, 1 the frame
// (GpuSkyFrame), 2 the surfaces, 3 the depth, 4 a nearest sampler, 5 the transmittance
// LUT, 6 a linear sampler, 7 the output; each variant's own inputs from binding 8 on.
constexpr uint32_t kFirstVariantBinding = 8;

class SkyExecution final : public PassExecution {
 public:
  explicit SkyExecution(const SkyTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, shader(s));
    atmosphere_.setup(s, program_);
    plumbing::check_uniform_mirror<GpuSkyFrame>(program_, 0, 1, s.name() + " frame");
    frame_ = s.device.create_buffer({s.name() + " frame", sizeof(GpuSkyFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    using rhi::BindGroupEntry;
    const GpuSkyFrame frame = sky_frame(c);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    std::vector<BindGroupEntry> entries = {
        BindGroupEntry::of(0, atmosphere_.write(c)),       BindGroupEntry::of(1, frame_),
        BindGroupEntry::of(2, c.view(t_.surfaces)),         BindGroupEntry::of(3, c.view(t_.depth)),
        BindGroupEntry::of(4, c.sampler(rhi::StockSampler::nearest_clamp)), BindGroupEntry::of(5, c.view(t_.transmittance)),
        BindGroupEntry::of(6, c.sampler(rhi::StockSampler::linear_clamp)),  BindGroupEntry::of(7, c.view(t_.sky_color))};
    uint32_t binding = kFirstVariantBinding;
    for (const rhi::TextureViewId view : variant_inputs(c)) entries.push_back(BindGroupEntry::of(binding++, view));
    plumbing::dispatch(c.encoder, c.name(), program_, {c.bind_group(program_.layouts[0], std::move(entries))}, c.extent(t_.sky_color));
  }

 private:
  // The variant's shader.
  std::string shader(const PassSetup& s) const {
    if (s.variant_is(t_.sky_view_lut)) return "atmosphere_sky.comp";
    return "atmosphere_sky.comp";
  }

  // The variant's own inputs, in its shader's binding order from kFirstVariantBinding.
  std::vector<rhi::TextureViewId> variant_inputs(PassContext& c) const {
    if (c.variant_is(t_.sky_view_lut)) return {c.view(t_.sky_view)};
    return {};
  }

  GpuSkyFrame sky_frame(const PassContext& c) const {
    const Atmosphere& a = *c.scene->atmosphere;
    const atmosphere::PlanetFrame planet = atmosphere::planet_frame(*c.scene);
    GpuSkyFrame f{};
    f.view = fog::pack_view_rays(c.scene->camera, c.extent(t_.sky_color));
    std::copy(std::begin(planet.planet_up), std::end(planet.planet_up), f.planet_up);
    std::copy(std::begin(planet.toward_sun), std::end(planet.toward_sun), f.toward_sun);
    for (size_t i = 0; i < 3 && planet.has_sun; ++i) f.sun[i] = float(c.scene->lights[size_t(a.sun_light)].irradiance[i]);
    f.sun[3] = planet.has_sun ? 1.0f : 0.0f;
    f.sun_disk[0] = float(a.sun_angular_radius);
    f.sun_disk[1] = c.param(t_.sun_disk) ? 1.0f : 0.0f;
    return f;
  }

  const SkyTable& t_;
  plumbing::ComputeProgram program_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId frame_;
};

}  // namespace

PassDecl sky_pass() { return pass_type<SkyTable, SkyExecution>(); }

}  // namespace volgraph
