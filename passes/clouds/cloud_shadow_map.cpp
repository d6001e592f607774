// cloud_shadow_map: the cloud layer's optical depth toward the sun over a square under the
// camera, for the surfaces below to be shadowed by exp(−τ) (the scene pass's optional
// `cloud_shadow`). Per texel of a `size` × `size` map, τ = ∫ σt(ρ(q + s·to_sun)) ds from
// the texel's point q on the layer's bottom plane through the layer, `steps` midpoint
// samples, the density cloud_march's (shaders/include/cloud_layer.glsl, the same text). The
// square's placement is cloud_shadow_view() (passes/clouds/cloud_shadow_view.h), written to
// `view` for the readers. Optional input `weather` (cloud_weather_map's): the coverage and
// type read there, as cloud_march does. With `layers` N > 0 also `optical_depth_layers`
// (Schneider & Vos 2015's transmittance map, size × size × N): slice k holds τ from the point
// at altitude bottom + (k + ½)/N · (top − bottom) on the same sun ray to the layer's top, by
// `steps` midpoint samples (cloud_march's transmittance_map variant reads it). Shaders: shaders/cloud_shadow_map.comp,
// cloud_shadow_map_weather.comp (include/cloud_shadow_map_body.glsl).
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/clouds/cloud_shadow_view.h"
#include "passes/clouds/cloud_weather_map.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "shaders/bindings/cloud_shadow_map.comp.h"
#include "shaders/bindings/cloud_shadow_map_weather.comp.h"

namespace volgraph {
namespace {

namespace cloud_shadow_map_shader = shaders::cloud_shadow_map_comp;

struct CloudShadowMapTable : PassTable {
  CloudShadowMapTable()
      : PassTable("cloud_shadow_map", PassKind::compute,
                  "The cloud layer's optical depth toward the sun over a square under the camera: the ground's cloud shadows.") {
    decl.needs = feature_bit(SceneFeature::clouds);
  }
  // Variants.
  VariantHandle optical_depth_variant = variant("optical_depth", "τ toward the sun by midpoint samples through the layer");
  // Parameters.
  ParamHandle<int64_t> size = integer("size", 256, 8, 4096, "texels", "side of the square map");
  ParamHandle<double> extent = number("extent", 40000, 1, 1e6, "m", "side of the square the map covers, centred under the camera");
  ParamHandle<int64_t> steps = integer("steps", 32, 1, 1024, "", "samples of the density along the sun's ray through the layer");
  ParamHandle<double> curl_strength = number("curl_strength", 0.1, 0, 1, "detail tiles", "cloud_march's curl_strength (keep them equal)");
  ParamHandle<int64_t> layers = integer("layers", 0, 0, 256, "",
                                        "slices of optical_depth_layers, the transmittance map (0: none, one unwritten slice)");
  // Slots.
  SlotHandle shape = input("shape", ResourceKind::texture3d, Usage::sampled, "cloud_noise.shape");
  SlotHandle detail = input("detail", ResourceKind::texture3d, Usage::sampled, "cloud_noise.detail");
  SlotHandle curl = input("curl", ResourceKind::texture2d, Usage::sampled, "cloud_noise.curl");
  SlotHandle weather = optional_input("weather", ResourceKind::texture2d, Usage::sampled,
                                      "cloud_weather_map.weather (cloud_march's: keep them equal); unbound: the layer's coverage and type");
  SlotHandle optical_depth = output("optical_depth", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                    SizeSpec::square_of(size), "r the optical depth τ toward the sun from the layer's bottom plane");
  SlotHandle optical_depth_layers =
      output("optical_depth_layers", ResourceKind::texture3d, Usage::storage_write, Format::rgba16_float, SizeSpec::square_layers_of(size, layers),
             "r τ toward the sun from altitude bottom + (k + ½)/layers · (top − bottom) on the texel's sun ray, slice k (layers > 0)",
             // Never aliased: bound (and written) even where nothing reads it, which an aliased transient's barriers miss.
             {.persistent = true});
  SlotHandle view = output("view", ResourceKind::buffer, Usage::copy_dst, Format::undefined, SizeSpec::bytes(sizeof(gpu::CloudShadowView)),
                           "the map's placement (shaders/include/cloud_shadow_view.h), for the passes that read it");
};

class CloudShadowMapExecution final : public PassExecution {
 public:
  explicit CloudShadowMapExecution(const CloudShadowMapTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    weathered_ = s.bound(t_.weather);
    program_ = plumbing::create_compute_program(s.device, weathered_ ? "cloud_shadow_map_weather.comp" : "cloud_shadow_map.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::CloudShadowMapParams>(program_, cloud_shadow_map_shader::params, s.name() + " params");
    params_ = s.device.create_buffer(
        {s.name() + " params", sizeof(gpu::CloudShadowMapParams), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  void record(PassContext& c) override {
    namespace shader = cloud_shadow_map_shader;
    const gpu::CloudShadowView view = cloud_shadow_view(*c.scene, c.param(t_.extent), int(c.param(t_.size)));
    const gpu::CloudShadowMapParams params = map_params(c, view);
    c.device.write_buffer(params_, 0, std::as_bytes(std::span(&params, 1)));
    c.encoder.update_buffer(c.buffer(t_.view), 0, std::as_bytes(std::span(&view, 1)));  // for the readers
    std::vector<rhi::BoundResource> entries = {
        bind(shader::params, params_), bind(shader::shape, c.view(t_.shape)), bind(shader::detail, c.view(t_.detail)),
        bind(shader::curl, c.view(t_.curl)), bind(shader::noise, c.sampler(rhi::StockSampler::linear_repeat)),
        bind(shader::optical_depth, c.view(t_.optical_depth)), bind(shader::optical_depth_layers, c.view(t_.optical_depth_layers))};
    if (weathered_) entries.push_back(bind(shaders::cloud_shadow_map_weather_comp::weather, c.view(t_.weather)));
    const rhi::BindGroupId group = c.bind_group(program_, entries);
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.optical_depth));
  }

 private:
  gpu::CloudShadowMapParams map_params(const PassContext& c, const gpu::CloudShadowView& view) const {
    const Scene& scene = *c.scene;
    const CloudLayer& layer = *scene.clouds;
    gpu::CloudShadowMapParams p{};
    p.plane = view.plane;
    p.to_sun = view.to_sun;
    p.layer[0] = float(layer.bottom_altitude), p.layer[1] = float(layer.top_altitude);
    p.layer[2] = float(clouds::planet_radius(scene));
    p.layer[3] = float(clouds::origin_altitude(scene));
    p.cloud[0] = float(layer.coverage), p.cloud[1] = float(layer.type), p.cloud[2] = float(layer.extinction);
    p.scales[0] = float(layer.shape_scale), p.scales[1] = float(layer.detail_scale), p.scales[2] = float(c.param(t_.curl_strength));
    const std::array<double, 3> wind = clouds::wind_offset(layer, c.frame);  // the clouds and their shadows move together
    for (int i = 0; i < 3; ++i) p.wind[i] = float(wind[size_t(i)]);
    const std::array<float, 4> weather = clouds::weather_lookup(layer);
    for (int i = 0; i < 4; ++i) p.weather[i] = weather[size_t(i)];
    p.steps[0] = int32_t(c.param(t_.steps));
    p.steps[1] = int32_t(c.param(t_.layers));
    return p;
  }

  const CloudShadowMapTable& t_;
  bool weathered_ = false;  // the weather input bound: cloud_shadow_map_weather.comp
  plumbing::ComputeProgram program_;
  rhi::BufferId params_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CloudShadowMapTable, CloudShadowMapExecution);

}  // namespace volgraph
