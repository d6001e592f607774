// light_shafts_screen: cheap light shafts in screen space (Mitchell 2007, GPU Gems 3 ch. 13;
// RTR4 §14.2.2): a radial blur of the sky's occlusion mask (the scene's depth at the far
// plane) toward the sun's position on the frame, with Mitchell's decay, weight, density and
// sample count, × the sun's irradiance × `exposure`, fading as the sun leaves the frame
// (`fade_margin` frame widths past its edge) and off behind the camera
// (physics/light_shafts.h). The output is fog_apply's pair, as the fog techniques', so
// `volgraph ab` compares it with them against the reference. Where it is wrong by design:
// occluders off the frame cast nothing, the medium's density and the light's colour along
// the way are ignored, shafts need the sun on or near the frame. Shader:
// shaders/light_shafts_screen.comp.
#include <span>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "physics/light_shafts.h"
#include "shaders/bindings/light_shafts_screen.comp.h"

namespace volgraph {
namespace {

namespace light_shafts_screen_shader = shaders::light_shafts_screen_comp;

struct LightShaftsScreenTable : PassTable {
  LightShaftsScreenTable()
      : PassTable("light_shafts_screen", PassKind::compute,
                  "Screen-space light shafts (Mitchell 2007): the sky's mask blurred radially toward the sun on the frame.") {
    decl.needs = feature_bit(SceneFeature::medium);
  }
  // Variants.
  VariantHandle radial_blur = variant("radial_blur", "Mitchell 2007's radial blur of the occlusion mask toward the sun");
  // Parameters.
  ParamHandle<int64_t> samples = integer("samples", 64, 1, 512, "", "steps from each pixel toward the sun");
  ParamHandle<double> density = number("density", 0.9, 0, 1, "", "the fraction of the way to the sun the steps cover");
  ParamHandle<double> weight = number("weight", 0.02, 0, 1, "", "each sample's weight");
  ParamHandle<double> decay = number("decay", 0.97, 0, 1, "", "each step's falloff");
  ParamHandle<double> exposure = number("exposure", 1, 0, 1e4, "1/sr", "the gathered sky × the sun's irradiance × this: radiance");
  ParamHandle<double> fade_margin = number("fade_margin", 0.25, 0, 10, "frames", "how far past the frame's edge the sun fades out");
  // Slots.
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (1: the sky)", {.format = Format::d32_float});
  SlotHandle fog_scattering = output("fog_scattering", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                     SizeSpec::of_output(), "the shafts' radiance, rgb (fog_apply's fog_scattering)");
  SlotHandle fog_transmittance = output("fog_transmittance", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                        SizeSpec::of_output(), "1: the shafts dim nothing (fog_apply's fog_transmittance)");
};

class LightShaftsScreenExecution final : public PassExecution {
 public:
  explicit LightShaftsScreenExecution(const LightShaftsScreenTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "light_shafts_screen.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::LightShaftsParams>(program_, light_shafts_screen_shader::params, s.name() + " params");
    params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::LightShaftsParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    namespace shader = light_shafts_screen_shader;
    const gpu::LightShaftsParams params = shaft_params(c);
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::params, params_), bind(shader::scene_depth, c.view(t_.depth)),
                   bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                   bind(shader::fog_scattering, c.view(t_.fog_scattering)), bind(shader::fog_transmittance, c.view(t_.fog_transmittance))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.fog_scattering));
  }

 private:
  gpu::LightShaftsParams shaft_params(const PassContext& c) const {
    const Scene& scene = *c.scene;
    gpu::LightShaftsParams p{};
    p.march[0] = float(c.param(t_.samples)), p.march[1] = float(c.param(t_.density));
    p.march[2] = float(c.param(t_.weight)), p.march[3] = float(c.param(t_.decay));
    const int sun = scene.sun_light();
    if (sun < 0) return p;  // no sun: no shafts (fade 0)
    const Light& light = scene.lights[size_t(sun)];
    const Vec3 to_sun = physics::normalize(Vec3{-light.direction[0], -light.direction[1], -light.direction[2]});
    const Extent frame = c.extent(t_.fog_scattering);
    const physics::ViewRays rays = physics::view_rays(scene.camera, double(frame.width) / double(frame.height));
    const physics::ScreenSun at = physics::screen_sun(rays, to_sun, c.param(t_.fade_margin));
    p.sun[0] = float(at.u), p.sun[1] = float(at.v), p.sun[2] = float(at.fade);
    for (int i = 0; i < 3; ++i) p.radiance[i] = float(light.irradiance[size_t(i)] * c.param(t_.exposure) * at.fade);
    return p;
  }

  const LightShaftsScreenTable& t_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(LightShaftsScreenTable, LightShaftsScreenExecution);

}  // namespace volgraph
