// atmosphere_aerial_perspective (Hillaire 2020 §5.4): the air between the camera and every
// point it sees, in a camera-frustum volume (`resolution`² columns through the frame,
// `slices` deep, slice k holding the ray's first (k + ½) · distance / slices m): the light
// the atmosphere scatters toward the camera over that stretch for a sun of unit
// illuminance, and the stretch's transmittance (physics::scattering_along: Rayleigh and Mie
// single scattering plus σs · Ψ_ms, the sun's transmittance and Ψ_ms from their LUTs).
// Surfaces, fog and clouds then take L·T + S·E from one lookup
// (include/atmosphere_aerial_lookup.glsl, with the volumes' frame this pass writes to
// `lookup`). 32 × 32 × 32 over 32 km as Hillaire 2020. Variant bruneton fills the same
// volumes from Bruneton 2017's precomputed scattering table
// (atmosphere_bruneton_tables.scattering and .single_mie_scattering: GetSkyRadianceToPoint, the scattering to the
// ray's boundary from the camera less the transmittance times that from
// the texel's point). Cached on the atmosphere and the camera. With cloud_shadow_map wired
// (hillaire only: Bruneton's tables hold unshadowed light) the cloud layer dims the sun at
// each sample by exp(−τ), so the air under the clouds' shadow scatters only the light the
// air itself has already scattered (Ψ_ms): include/atmosphere_sky.glsl's sun-visibility hook.
// Shaders: shaders/atmosphere_aerial_perspective.comp, atmosphere_aerial_perspective_cloud_shadowed.comp
// (include/atmosphere_aerial_perspective_body.glsl), atmosphere_aerial_perspective_bruneton.comp.
#include <algorithm>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/register_pass.h"
#include "passes/atmosphere/bruneton_uniforms.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/uniform_mirrors.h"
#include "physics/atmosphere.h"
#include "physics/atmosphere_sky.h"
#include "shaders/bindings/atmosphere_aerial_perspective.comp.h"
#include "shaders/bindings/atmosphere_aerial_perspective_bruneton.comp.h"
#include "shaders/bindings/atmosphere_aerial_perspective_cloud_shadowed.comp.h"
#include "shaders/include/cloud_shadow_view.h"

namespace volgraph {
namespace {

namespace atmosphere_aerial_perspective_shader = shaders::atmosphere_aerial_perspective_comp;
namespace atmosphere_aerial_perspective_bruneton_shader = shaders::atmosphere_aerial_perspective_bruneton_comp;
namespace aerial_cloud_shadowed_shader = shaders::atmosphere_aerial_perspective_cloud_shadowed_comp;

struct AerialPerspectiveTable : PassTable {
  AerialPerspectiveTable()
      : PassTable("atmosphere_aerial_perspective", PassKind::compute,
                  "The air's in-scattering and transmittance in a camera-frustum volume (Hillaire 2020, or from Bruneton 2017's tables).") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
    decl.cached = true;
    decl.frame_invariant = true;
    decl.reads_scene = part_bit(ScenePart::atmosphere) | part_bit(ScenePart::camera);
  }
  // Variants.
  VariantHandle hillaire = variant("hillaire", "each texel integrates its ray from the camera to its slice (Hillaire 2020 §5.4)");
  VariantHandle bruneton = variant("bruneton", "each texel from two lookups in Bruneton 2017's scattering table (GetSkyRadianceToPoint)");
  // Parameters.
  ParamHandle<int64_t> resolution = integer("resolution", 32, 2, 512, "texels", "columns per side through the frame");
  ParamHandle<int64_t> slices = integer("slices", 32, 1, 512, "", "slices along each ray");
  ParamHandle<double> distance = number("distance", 32e3, 1, 1e7, "m", "how far along each ray the volume reaches");
  ParamHandle<double> samples = number("samples", 40, 1, 512, "", "midpoint samples from the camera to each slice (hillaire)");
  // Slots.
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled,
                                   "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle multiscattering = optional_input("multiscattering", ResourceKind::texture2d, Usage::sampled,
                                              "hillaire: the multiple-scattering LUT (atmosphere_multiscattering_lut.multiscattering)", {.required_in = {hillaire}});
  SlotHandle scattering = optional_input("scattering", ResourceKind::texture3d, Usage::sampled,
                                         "bruneton: the scattering table (atmosphere_bruneton_tables.scattering)", {.required_in = {bruneton}});
  SlotHandle single_mie_scattering = optional_input("single_mie_scattering", ResourceKind::texture3d, Usage::sampled,
                                                    "bruneton: the single Mie table (atmosphere_bruneton_tables.single_mie_scattering)", {.required_in = {bruneton}});
  SlotHandle cloud_shadow = optional_input("cloud_shadow", ResourceKind::texture2d, Usage::sampled,
                                           "hillaire: cloud_shadow_map's optical depth: the cloud layer dims the sun by exp(−τ) at each sample",
                                           {.format = Format::rgba16_float, .read_in = {hillaire}});
  SlotHandle cloud_shadow_view = optional_input("cloud_shadow_view", ResourceKind::buffer, Usage::uniform_read,
                                                "hillaire: cloud_shadow_map's view (where its square lies, toward which sun)",
                                                {.read_in = {hillaire}});
  SlotHandle aerial_scattering = output("aerial_scattering", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                                        SizeSpec::square_layers_of(resolution, slices),
                                        "rgb scattered toward the camera from it to each texel, for a sun of unit illuminance");
  SlotHandle aerial_transmittance = output("aerial_transmittance", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float,
                                           SizeSpec::square_layers_of(resolution, slices), "rgb transmittance from the camera to each texel");
  SlotHandle lookup = output("lookup", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(kAerialLookupBytes),
                             "the volumes' frame for the passes that read them (include/atmosphere_aerial_lookup.glsl AerialLookup)");
};

class AerialPerspectiveExecution final : public PassExecution {
 public:
  explicit AerialPerspectiveExecution(const AerialPerspectiveTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    bruneton_ = s.variant_is(t_.bruneton);  // the loader made sure the variant's input is wired
    cloud_shadowed_ = s.bound(t_.cloud_shadow) && s.bound(t_.cloud_shadow_view);  // hillaire only (SlotOptions::read_in)
    program_ = plumbing::create_compute_program(s.device, shader_name());
    atmosphere_.setup(s, program_);
    if (cloud_shadowed_)
      plumbing::check_wrapped_uniform_mirror<gpu::CloudShadowView>(program_, aerial_cloud_shadowed_shader::cloud_shadow_view, s.name() + " cloud_shadow_view");
    plumbing::check_wrapped_uniform_mirror<gpu::AerialPerspectiveFrame>(program_, 0, 1, s.name() + " frame");
    frame_ = s.device.create_buffer({s.name() + " frame", sizeof(gpu::AerialPerspectiveFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    if (bruneton_) table_ = plumbing::create_shared_uniform_block(s.device, program_, atmosphere_aerial_perspective_bruneton_shader::table, s.name() + " table", table_shape(s));
  }

  void record(PassContext& c) override {
    const gpu::AerialPerspectiveFrame frame = aerial_frame(c);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    // The volumes' frame for their readers, whichever variant fills them.
    const gpu::AerialLookup lookup = aerial_lookup(c);
    c.encoder.update_buffer(c.buffer(t_.lookup), 0, std::as_bytes(std::span(&lookup, 1)));
    if (bruneton_) {
      record_bruneton(c);
      return;
    }
    const rhi::BindGroupId group = c.bind_group(
        program_,
        {bind(atmosphere_aerial_perspective_shader::atmosphere, atmosphere_.write(c)), bind(atmosphere_aerial_perspective_shader::frame, frame_), bind(atmosphere_aerial_perspective_shader::transmittance, c.view(t_.transmittance)),
         bind(atmosphere_aerial_perspective_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(atmosphere_aerial_perspective_shader::multiscattering, c.view(t_.multiscattering)),
         bind(atmosphere_aerial_perspective_shader::linear, c.sampler(rhi::StockSampler::linear_clamp)), bind(atmosphere_aerial_perspective_shader::aerial_scattering, c.view(t_.aerial_scattering)),
         bind(atmosphere_aerial_perspective_shader::aerial_transmittance, c.view(t_.aerial_transmittance))});
    rhi::BindGroupId cloud_shadow;
    if (cloud_shadowed_) {
      cloud_shadow = c.bind_group(program_, {bind(aerial_cloud_shadowed_shader::cloud_shadow, c.view(t_.cloud_shadow)),
                                             bind(aerial_cloud_shadowed_shader::cloud_shadow_sampler, c.sampler(rhi::StockSampler::linear_clamp)),
                                             bind(aerial_cloud_shadowed_shader::cloud_shadow_view, c.buffer(t_.cloud_shadow_view))});
    }
    const Extent size = c.extent(t_.aerial_scattering);
    plumbing::dispatch(c.encoder, c.name(), program_, {group, cloud_shadow}, {size.width, size.height, size.depth});
  }

 private:
  const char* shader_name() const {
    if (bruneton_) return "atmosphere_aerial_perspective_bruneton.comp";
    return cloud_shadowed_ ? "atmosphere_aerial_perspective_cloud_shadowed.comp" : "atmosphere_aerial_perspective.comp";
  }

  // bruneton: the scattering table's shape, its nu slices those of the tables pass that
  // made it (atmosphere_bruneton_tables.nu: one source, so a reader never disagrees).
  gpu::BrunetonTableParams table_shape(const PassSetup& s) const {
    const Extent e = s.extent(t_.scattering);
    return bruneton_table_shape(e.width, e.height, e.depth, s.producer_param(t_.scattering, "nu"));
  }

  void record_bruneton(PassContext& c) const {
    const rhi::BindGroupId group = c.bind_group(
        program_,
        {bind(atmosphere_aerial_perspective_bruneton_shader::atmosphere, atmosphere_.write(c)), bind(atmosphere_aerial_perspective_bruneton_shader::frame, frame_), bind(atmosphere_aerial_perspective_bruneton_shader::transmittance, c.view(t_.transmittance)),
         bind(atmosphere_aerial_perspective_bruneton_shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(atmosphere_aerial_perspective_bruneton_shader::scattering, c.view(t_.scattering)),
         bind(atmosphere_aerial_perspective_bruneton_shader::table, table_), bind(atmosphere_aerial_perspective_bruneton_shader::aerial_scattering, c.view(t_.aerial_scattering)),
         bind(atmosphere_aerial_perspective_bruneton_shader::aerial_transmittance, c.view(t_.aerial_transmittance)), bind(atmosphere_aerial_perspective_bruneton_shader::single_mie_scattering, c.view(t_.single_mie_scattering))});
    const Extent size = c.extent(t_.aerial_scattering);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, {size.width, size.height, size.depth});
  }

  gpu::AerialPerspectiveFrame aerial_frame(const PassContext& c) const {
    const atmosphere::PlanetFrame planet = atmosphere::planet_frame(*c.scene);
    gpu::AerialPerspectiveFrame f{};
    f.view = fog::pack_view_rays(c.scene->camera, c.frame_size());
    f.planet_up = gpu::vec4_of(planet.planet_up);
    f.toward_sun = gpu::vec4_of(planet.toward_sun);
    f.volume[0] = float(c.param(t_.distance) / double(c.param(t_.slices)));
    f.volume[1] = planet.has_sun ? 1.0f : 0.0f;
    const float samples = float(c.param(t_.samples));
    f.sampling[0] = samples;
    f.sampling[1] = samples;
    f.sampling[2] = 100e3f;
    f.sampling[3] = 0.5f;
    return f;
  }

  gpu::AerialLookup aerial_lookup(const PassContext& c) const {
    gpu::AerialLookup l{};
    l.view = fog::pack_view_rays(c.scene->camera, c.frame_size());
    l.volume[0] = float(c.param(t_.distance));
    l.volume[1] = float(c.param(t_.slices));
    const atmosphere::PlanetFrame planet = atmosphere::planet_frame(*c.scene);
    l.sun = gpu::vec4_of(planet.sun);
    l.sun.w = 0;  // the block has no flag
    return l;
  }

  const AerialPerspectiveTable& t_;
  bool bruneton_ = false;
  bool cloud_shadowed_ = false;  // cloud_shadow and its view wired: atmosphere_aerial_perspective_cloud_shadowed.comp
  plumbing::ComputeProgram program_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId frame_, table_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(AerialPerspectiveTable, AerialPerspectiveExecution);

}  // namespace volgraph
