// sky_cube: the atmosphere's sky in every direction around the camera, a cube map
// (ResourceKind::texture_cube) for what reflects or refracts it: translucency's
// environment — its reflections F·L_env and the refracted rays screen space cannot follow.
// Each texel holds the sky toward its centre exactly as the sky pass draws it behind the
// scene (Hillaire 2020: the sky-view LUT, the ground, the march from space; one GLSL text,
// include/atmosphere_sky_toward.glsl), times the sun's irradiance. The sun's disk is off by
// default: it spans 0.27° where a 64-texel face's texel spans ~1.4°, so a texel would
// hold it whole or not at all. Remade every frame (the sky follows the sun and the camera).
// Shader: shaders/sky_cube.comp.
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/atmosphere/atmosphere_block.h"
#include "passes/atmosphere/sky_pass_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "passes/uniform_mirrors.h"
#include "shaders/bindings/sky_cube.comp.h"

namespace volgraph {
namespace {

namespace sky_cube_shader = shaders::sky_cube_comp;

struct SkyCubeTable : PassTable {
  SkyCubeTable()
      : PassTable("sky_cube", PassKind::compute, "The atmosphere's sky in every direction around the camera, as a cube map (reflections, refraction).") {
    decl.needs = feature_bit(SceneFeature::atmosphere);
  }
  // Variants.
  VariantHandle sky_view_lut = variant("sky_view_lut", "each texel the sky-view LUT toward its centre, the ground below the horizon (Hillaire 2020), as the sky pass draws it");
  // Parameters.
  ParamHandle<int64_t> size = integer("size", 64, 1, 2048, "texels", "each face's side");
  ParamHandle<bool> sun_disk = flag("sun_disk", false, "put the sun's disk in the texels it falls in (off: a texel is far wider than the disk)");
  ParamHandle<bool> ground = flag("ground", true, "the planet's Lambertian ground below the horizon (lit by the sun through the air and by the sky)");
  ParamHandle<bool> multiscattering_term = flag("multiscattering", true, "Ψ_ms in the ground's light and in the march from space, where the LUT is wired");
  // Slots.
  SlotHandle transmittance = input("transmittance", ResourceKind::texture2d, Usage::sampled, "the transmittance LUT (atmosphere_transmittance_lut.transmittance)");
  SlotHandle sky_view = input("sky_view", ResourceKind::texture2d, Usage::sampled, "the sky-view LUT (atmosphere_skyview_lut.sky_view)");
  SlotHandle multiscattering = optional_input("multiscattering", ResourceKind::texture2d, Usage::sampled,
                                              "the multiple-scattering LUT (atmosphere_multiscattering_lut.multiscattering): the ground's sky light, the view from space");
  SlotHandle cube = output("cube", ResourceKind::texture_cube, Usage::storage_write, Format::rgba16_float, SizeSpec::square_of(size),
                           "the sky's radiance toward each texel's centre, faces +x, −x, +y, −y, +z, −z");
};

class SkyCubeExecution final : public PassExecution {
 public:
  explicit SkyCubeExecution(const SkyCubeTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "sky_cube.comp");
    atmosphere_.setup(s, program_);
    plumbing::check_wrapped_uniform_mirror<gpu::SkyPassFrame>(program_, 0, 1, s.name() + " frame");
    frame_ = s.device.create_buffer({s.name() + " frame", sizeof(gpu::SkyPassFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    namespace shader = sky_cube_shader;
    const bool has_multiscattering = c.bound(t_.multiscattering);
    atmosphere::SkyLook look;
    look.sun_disk = c.param(t_.sun_disk);
    look.ground = c.param(t_.ground);
    look.multiscattering = c.param(t_.multiscattering_term) && has_multiscattering;
    const Extent face = c.extent(t_.cube);
    const gpu::SkyPassFrame frame = atmosphere::sky_pass_frame(*c.scene, face, look);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::atmosphere, atmosphere_.write(c)), bind(shader::frame, frame_), bind(shader::transmittance, c.view(t_.transmittance)),
                   bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(shader::linear, c.sampler(rhi::StockSampler::linear_clamp)),
                   bind(shader::sky_view, c.view(t_.sky_view)),
                   bind(shader::multiscattering, c.view(has_multiscattering ? t_.multiscattering : t_.sky_view)),
                   bind(shader::cube, c.view(t_.cube, 0))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, {face.width, face.height, array_layers(ResourceKind::texture_cube)});
  }

 private:
  const SkyCubeTable& t_;
  plumbing::ComputeProgram program_;
  atmosphere::AtmosphereBlock atmosphere_;
  rhi::BufferId frame_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(SkyCubeTable, SkyCubeExecution);

}  // namespace volgraph
