// cloud_march: the cloud layer drawn by a per-pixel ray march (Schneider & Vos 2015; RTR4
// 14.4.2). Per pixel: the view ray against the layer's two spheres on the planet (the
// atmosphere's radius, else Earth's 6,360 km), the segment inside the layer (clipped by
// the scene's surface and `max_distance`) marched in `steps` equal steps with empty-space
// skipping, the density of shaders/include/cloud_density.h on cloud_noise's textures
// drifted by the wind, the sun's visibility by a secondary march of `light_steps`, the
// lighting of shaders/include/cloud_lighting.h (dual-lobe HG, Wrenninge's octaves, the
// optional powder term) plus the ambient radiance, integrated by Hillaire's step.
// Outputs: `clouds` (rgb in-scattered radiance, a transmittance) and `transmittance` (the
// transmittance in rgb), the pair fog_apply composites (fog_scattering ← clouds,
// fog_transmittance ← transmittance). Optional input `weather` (cloud_weather_map's): the
// coverage and type read there. Variant `transmittance_map` (Schneider & Vos 2015): the
// sun's optical depth read trilinearly from cloud_shadow_map's optical_depth_layers (inputs
// sun_optical_depth and sun_optical_depth_view, required there) at the sample's column and
// altitude, the secondary march only outside the map. Optional input `phase_table`
// (cloud_phase_table's, shaders/include/cloud_phase_table.h): the phase per channel read from
// the table (a Mie phase of droplets) instead of the dual-lobe HG (g_forward, g_back and
// back_weight then unused). Shaders: shaders/cloud_march.comp, cloud_march_weather.comp,
// cloud_march_transmittance_map.comp, cloud_march_weather_transmittance_map.comp, and each
// with _phase_table (include/cloud_march_body.glsl).
#include <array>
#include <optional>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/clouds/cloud_blocks.h"
#include "passes/clouds/cloud_layer.h"
#include "passes/clouds/cloud_weather_map.h"
#include "passes/fog/fog_frame.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "physics/atmosphere_lighting.h"
#include "shaders/bindings/cloud_march.comp.h"
#include "shaders/bindings/cloud_march_phase_table.comp.h"
#include "shaders/bindings/cloud_march_transmittance_map.comp.h"
#include "shaders/bindings/cloud_march_weather.comp.h"
#include "shaders/bindings/cloud_march_weather_transmittance_map.comp.h"
#include "shaders/include/cloud_shadow_view.h"

namespace volgraph {
namespace {

namespace cloud_march_shader = shaders::cloud_march_comp;

std::vector<ParamProblem> octave_problems(const PassDecl& decl, const Scene&, const std::vector<ParamValue>& params);

struct CloudMarchTable : PassTable {
  CloudMarchTable()
      : PassTable("cloud_march", PassKind::compute,
                  "The cloud layer by a per-pixel ray march (Schneider & Vos 2015): in-scattered radiance and transmittance.") {
    decl.needs = feature_bit(SceneFeature::clouds);
    decl.check_scene = octave_problems;
  }
  // Variants.
  VariantHandle march = variant("march", "the sun's visibility by a secondary march of light_steps toward it");
  VariantHandle transmittance_map = variant("transmittance_map",
                                            "the sun's optical depth read from cloud_shadow_map's optical_depth_layers, made once per "
                                            "frame (Schneider & Vos 2015); the secondary march only outside the map");
  // Parameters.
  ParamHandle<int64_t> steps = integer("steps", 64, 1, 1024, "", "equal steps over the ray's segment inside the layer");
  ParamHandle<int64_t> light_steps = integer("light_steps", 16, 1, 64, "", "samples of the density toward the sun per step (march; transmittance_map: outside the map only)");
  ParamHandle<double> light_distance = number("light_distance", 2000, 1, 1e5, "m", "how far toward the sun the light march reaches (march; transmittance_map: outside the map only)");
  ParamHandle<int64_t> octaves = integer("octaves", 3, 1, 8, "", "Wrenninge's multiple-scattering octaves (1: single scattering)");
  ParamHandle<double> a = number("a", 0.5, 0, 1, "", "each octave's optical-depth scale (a ≤ b)");
  ParamHandle<double> b = number("b", 0.5, 0, 1, "", "each octave's energy scale");
  ParamHandle<double> c = number("c", 0.5, 0, 1, "", "each octave's phase-anisotropy scale");
  ParamHandle<double> g_forward = number("g_forward", 0.8, -0.998, 0.998, "", "the forward HG lobe's g");
  ParamHandle<double> g_back = number("g_back", -0.3, -0.998, 0.998, "", "the backward HG lobe's g");
  ParamHandle<double> back_weight = number("back_weight", 0.2, 0, 1, "", "the backward lobe's weight");
  ParamHandle<bool> powder = flag("powder", false, "Schneider & Vos's powder term (not physical: darkens sunlit edges, adds energy inside)");
  ParamHandle<double> max_distance = number("max_distance", 60000, 1, 1e7, "m", "how far along the view ray the march reaches");
  ParamHandle<double> curl_strength = number("curl_strength", 0.1, 0, 1, "detail tiles", "how far the curl noise shifts the detail");
  ParamHandle<std::array<double, 3>> ambient =
      vec3("ambient", {0, 0, 0}, 0, 1e6, "W/(m²·sr)", "uniform radiance the cloud scatters (with an atmosphere: the sky's, added)");
  ParamHandle<bool> jitter = flag("jitter", true,
                                  "sample each fine step at a per-pixel, per-frame point (interleaved gradient noise); off: its midpoint");
  ParamHandle<int64_t> update_block = integer("update_block", 1, 1, 4, "pixels",
                                              "march one pixel of each block this wide per frame (Bayer order; 1, 2 or 4): the "
                                              "outputs are the frame divided by it, cloud_temporal rebuilds the rest");
  // The outputs' size: the frame divided by update_block (one texel per block).
  SizeSpec block_size() const {
    SizeSpec s = SizeSpec::of_output();
    s.divisor_param = update_block.index;
    return s;
  }
  // Slots.
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth", {.format = Format::d32_float});
  SlotHandle shape = input("shape", ResourceKind::texture3d, Usage::sampled, "cloud_noise.shape");
  SlotHandle detail = input("detail", ResourceKind::texture3d, Usage::sampled, "cloud_noise.detail");
  SlotHandle curl = input("curl", ResourceKind::texture2d, Usage::sampled, "cloud_noise.curl");
  SlotHandle weather = optional_input("weather", ResourceKind::texture2d, Usage::sampled,
                                      "cloud_weather_map.weather: coverage and type per place (unbound: the layer's everywhere)");
  SlotHandle phase_table = optional_input("phase_table", ResourceKind::texture2d, Usage::sampled,
                                          "cloud_phase_table.phase: p(θ) per channel (unbound: the dual-lobe HG of g_forward, g_back, back_weight)");
  SlotHandle sun_optical_depth =
      optional_input("sun_optical_depth", ResourceKind::texture3d, Usage::sampled,
                     "cloud_shadow_map.optical_depth_layers (layers > 0): τ toward the sun per column and altitude, for transmittance_map",
                     {.required_in = {transmittance_map}});
  SlotHandle sun_optical_depth_view = optional_input("sun_optical_depth_view", ResourceKind::buffer, Usage::uniform_read,
                                                     "cloud_shadow_map.view: the map's placement, for transmittance_map",
                                                     {.required_in = {transmittance_map}});
  SlotHandle clouds = output("clouds", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, block_size(),
                             "rgb the layer's in-scattered radiance toward the camera, a the transmittance through it");
  SlotHandle transmittance = output("transmittance", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                    block_size(), "the transmittance through the layer in rgb (fog_apply's fog_transmittance)");
  SlotHandle distance = output("distance", ResourceKind::texture2d, Usage::storage_write, Format::r32_float, block_size(),
                               "the clouds' depth: the opacity-weighted mean distance (m) of the march's samples (the layer's entry "
                               "where it met no cloud, 0 where the ray misses the layer)");
};

// Wrenninge et al. 2013's energy condition a ≤ b (RTR4 14.4.2): refused with one message.
// The parameters are read through the table's handles, so a misspelt one does not compile.
std::vector<ParamProblem> octave_problems(const PassDecl& decl, const Scene&, const std::vector<ParamValue>& params) {
  static const CloudMarchTable table;
  // The Bayer order that names each frame's pixel exists for powers of two only.
  if (const int64_t block = param_in(params, table.update_block); !clouds::valid_update_block(block)) {
    return {{param_name(decl, table.update_block), "update_block (" + std::to_string(block) +
                                                       ") must be 1, 2 or 4 (the Bayer order of each block's pixels is defined for powers of two)"}};
  }
  const double a = param_in(params, table.a);
  const double b = param_in(params, table.b);
  if (a <= b) return {};
  std::ostringstream message;
  message << "a (" << a << ") must not exceed b (" << b
          << "): the octaves' extinction scale above their energy scale breaks energy conservation (Wrenninge et al. 2013)";
  return {{param_name(decl, table.a), message.str()}};
}

void copy4(gpu::vec4& to, const gpu::vec4& from) {
  for (int i = 0; i < 4; ++i) to[i] = from[i];
}

class CloudMarchExecution final : public PassExecution {
 public:
  explicit CloudMarchExecution(const CloudMarchTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    weathered_ = s.bound(t_.weather);
    tabulated_ = s.bound(t_.phase_table);
    mapped_ = s.variant_is(t_.transmittance_map);
    program_ = plumbing::create_compute_program(s.device, shader_name());
    plumbing::check_wrapped_uniform_mirror<gpu::CloudMarchParams>(program_, cloud_march_shader::params, s.name() + " params");
    if (mapped_)
      plumbing::check_wrapped_uniform_mirror<gpu::CloudShadowView>(program_, shaders::cloud_march_transmittance_map_comp::sun_optical_depth_view,
                                                                   s.name() + " sun_optical_depth_view");
    params_ = s.device.create_buffer({s.name() + " params", sizeof(gpu::CloudMarchParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    namespace shader = cloud_march_shader;
    const gpu::CloudMarchParams params = march_params(c, layer_light(*c.scene));
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    std::vector<rhi::BoundResource> entries = {
        bind(shader::params, params_), bind(shader::scene_depth, c.view(t_.depth)),
        bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)), bind(shader::shape, c.view(t_.shape)),
        bind(shader::detail, c.view(t_.detail)), bind(shader::curl, c.view(t_.curl)),
        bind(shader::noise, c.sampler(rhi::StockSampler::linear_repeat)), bind(shader::clouds, c.view(t_.clouds)),
        bind(shader::cloud_transmittance, c.view(t_.transmittance)), bind(shader::cloud_distance, c.view(t_.distance))};
    if (weathered_) entries.push_back(bind(shaders::cloud_march_weather_comp::weather, c.view(t_.weather)));
    if (tabulated_) entries.push_back(bind(shaders::cloud_march_phase_table_comp::phase_table, c.view(t_.phase_table)));
    if (mapped_) {
      namespace mapped = shaders::cloud_march_transmittance_map_comp;
      entries.push_back(bind(mapped::sun_optical_depth, c.view(t_.sun_optical_depth)));
      entries.push_back(bind(mapped::sun_optical_depth_view, c.buffer(t_.sun_optical_depth_view)));
      entries.push_back(bind(mapped::map_linear, c.sampler(rhi::StockSampler::linear_clamp)));
    }
    const rhi::BindGroupId group = c.bind_group(program_, entries);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.clouds));
  }

 private:
  // The permutation: the weather map bound, the variant transmittance_map, the phase table bound.
  std::string shader_name() const {
    std::string name = "cloud_march";
    if (weathered_) name += "_weather";
    if (mapped_) name += "_transmittance_map";
    if (tabulated_) name += "_phase_table";
    return name + ".comp";
  }

  // The atmosphere's light at the layer's middle altitude (physics/atmosphere_lighting.h),
  // kept until the atmosphere, its sun or the layer changes: Ψ_ms costs the CPU ~10 ms.
  const physics::LightAtAltitude& layer_light(const Scene& scene) {
    const uint64_t hash = scene.hash(part_bit(ScenePart::atmosphere) | part_bit(ScenePart::lights) | part_bit(ScenePart::clouds));
    if (light_hash_ != hash) {
      light_ = physics::atmosphere_light_at_altitude(scene, physics::cloud_light_altitude(*scene.clouds));
      light_hash_ = hash;
    }
    return light_;
  }

  gpu::CloudMarchParams march_params(const PassContext& c, const physics::LightAtAltitude& air) const {
    const Scene& scene = *c.scene;
    const CloudLayer& layer = *scene.clouds;
    gpu::CloudMarchParams p{};
    const gpu::ViewRays view = fog::pack_view_rays(scene.camera, c.frame_size());
    copy4(p.view_position, view.position);
    copy4(p.view_forward, view.forward);
    copy4(p.view_right, view.right);
    copy4(p.view_up, view.up);
    if (const int sun = clouds::sun_index(scene); sun >= 0) {
      const Light& light = scene.lights[size_t(sun)];
      const double n = std::sqrt(light.direction[0] * light.direction[0] + light.direction[1] * light.direction[1] +
                                 light.direction[2] * light.direction[2]);
      p.sun[0] = float(-light.direction[0] / n), p.sun[1] = float(-light.direction[1] / n), p.sun[2] = float(-light.direction[2] / n);
      p.sun[3] = 1;
      // With an atmosphere its sun arrives through the air above the layer, else as given.
      const Vec3& e = air.has_sun ? air.sun_irradiance : light.irradiance;
      for (int i = 0; i < 3; ++i) p.sun_irradiance[i] = float(e[size_t(i)]);
    }
    const std::array<double, 3> ambient = c.param(t_.ambient);
    for (int i = 0; i < 3; ++i) p.ambient[i] = float(ambient[size_t(i)] + air.sky_radiance[size_t(i)]);  // the sky's, added
    p.layer[0] = float(layer.bottom_altitude), p.layer[1] = float(layer.top_altitude);
    p.layer[2] = float(clouds::planet_radius(scene)), p.layer[3] = float(clouds::origin_altitude(scene));
    p.cloud[0] = float(layer.coverage), p.cloud[1] = float(layer.type), p.cloud[2] = float(layer.extinction);
    p.cloud[3] = float(c.param(t_.max_distance));
    p.scales[0] = float(layer.shape_scale), p.scales[1] = float(layer.detail_scale);
    p.scales[2] = float(c.param(t_.curl_strength)), p.scales[3] = float(c.param(t_.light_distance));
    const std::array<double, 3> wind = clouds::wind_offset(layer, c.frame);
    p.wind[0] = float(wind[0]), p.wind[1] = float(wind[1]), p.wind[2] = float(wind[2]);
    p.wind[3] = float(c.frame % 64);  // the jitter's frame: interleaved gradient noise scrolls over 64 frames
    const std::array<float, 4> weather = clouds::weather_lookup(layer);
    for (int i = 0; i < 4; ++i) p.weather[i] = weather[size_t(i)];
    p.steps[0] = int32_t(c.param(t_.steps)), p.steps[1] = int32_t(c.param(t_.light_steps)), p.steps[2] = int32_t(c.param(t_.octaves));
    p.steps[3] = c.param(t_.jitter) ? 1 : 0;
    p.octave[0] = float(c.param(t_.a)), p.octave[1] = float(c.param(t_.b)), p.octave[2] = float(c.param(t_.c));
    p.octave[3] = c.param(t_.powder) ? 1.0f : 0.0f;
    p.lobes[0] = float(c.param(t_.g_forward)), p.lobes[1] = float(c.param(t_.g_back)), p.lobes[2] = float(c.param(t_.back_weight));
    const int block = int(c.param(t_.update_block));
    const std::array<int32_t, 2> offset = clouds::marched_offset(c.frame, block);
    p.block[0] = block, p.block[1] = offset[0], p.block[2] = offset[1];
    p.frame[0] = int32_t(c.frame_size().width), p.frame[1] = int32_t(c.frame_size().height);
    return p;
  }

  const CloudMarchTable& t_;
  bool weathered_ = false;  // the weather input bound: cloud_march_weather*.comp
  bool mapped_ = false;     // the variant transmittance_map: cloud_march*_transmittance_map*.comp
  bool tabulated_ = false;  // the phase_table input bound: cloud_march*_phase_table.comp
  std::optional<uint64_t> light_hash_;
  physics::LightAtAltitude light_;
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CloudMarchTable, CloudMarchExecution);

}  // namespace volgraph
