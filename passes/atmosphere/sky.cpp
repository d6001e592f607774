// sky: the atmosphere seen where the scene's camera sees no surface (depth at the far
// plane): the sky-view LUT's radiance in the pixel's direction (its latitude and azimuth
// from the sun around the camera, Hillaire 2020 §5.3) times the sun's irradiance E, plus
// the sun's disk — radiance E / (π sin²α) within its angular radius α, dimmed by the
// atmosphere's transmittance toward it (the transmittance LUT). Surfaces keep the scene's
// colour (aerial perspective comes with its own pass). Shader: shaders/atmosphere_sky.comp.
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
  SkyTable() : PassTable("sky", PassKind::compute, "The atmosphere's sky and sun disk behind the scene's surfaces (Hillaire 2020's sky-view LUT).") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
  }
  // Variants.
  VariantHandle sky_view_lut = variant("sky_view_lut", "the sky from the sky-view LUT (bilinear), the sun disk through the transmittance LUT");
  // Parameters.
  ParamHandle<bool> sun_disk = flag("sun_disk", true, "draw the sun's disk");
  // Slots.
  SlotHandle surfaces = input("surfaces", ResourceKind::texture2d, Usage::sampled, "the scene's linear radiance (scene.color)");
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth", {.format = Format::d32_float});
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled,
                                   "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle sky_view = input("sky_view", ResourceKind::texture2d, Usage::sampled, "the sky-view LUT (atmosphere_skyview_lut.sky_view)");
  SlotHandle sky_color = output("color", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                                "the scene's radiance with the sky behind it", {.size_overridable = true});
};

class SkyExecution final : public PassExecution {
 public:
  explicit SkyExecution(const SkyTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "atmosphere_sky.comp");
    atmosphere_.setup(s, program_);
    plumbing::check_uniform_mirror<GpuSkyFrame>(program_, 0, 1, s.name() + " frame");
    frame_ = s.device.create_buffer({s.name() + " frame", sizeof(GpuSkyFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    using rhi::BindGroupEntry;
    const GpuSkyFrame frame = sky_frame(c);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    const rhi::SamplerId nearest = c.sampler(rhi::StockSampler::nearest_clamp), linear = c.sampler(rhi::StockSampler::linear_clamp);
    const rhi::BindGroupId group = c.bind_group(
        program_.layouts[0],
        {BindGroupEntry::of(0, atmosphere_.write(c)), BindGroupEntry::of(1, frame_), BindGroupEntry::of(2, c.view(t_.surfaces)),
         BindGroupEntry::of(3, c.view(t_.depth)), BindGroupEntry::of(4, nearest), BindGroupEntry::of(5, c.view(t_.transmittance)),
         BindGroupEntry::of(6, c.view(t_.sky_view)), BindGroupEntry::of(7, linear), BindGroupEntry::of(8, c.view(t_.sky_color))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.sky_color));
  }

 private:
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
