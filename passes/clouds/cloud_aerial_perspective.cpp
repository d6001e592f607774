// cloud_aerial_perspective: the air between the camera and the clouds (Hillaire 2016,
// "Physically Based Sky, Atmosphere and Cloud Rendering in Frostbite": aerial perspective
// applied to the clouds at their transmittance-weighted mean depth). cloud_march's
// `clouds` (rgb radiance L, a transmittance T_c) read at cloud_march's `distance` t̄ in
// atmosphere_aerial_perspective's volumes: L·T_air(t̄) + S_air(t̄)·E·(1 − T_c), a kept. The
// sky behind a cloud already holds its whole ray's air; where the cloud hides it, the air
// in front of the cloud takes its place. Volumes reach `distance` (32 km by default);
// beyond, their last slice is read (as aerial_perspective_apply does for surfaces).
// Shader: shaders/cloud_aerial_perspective.comp.
#include "graph/execute/pass_execution.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/programs.h"
#include "passes/register_pass.h"
#include "passes/uniform_mirrors.h"
#include "shaders/bindings/cloud_aerial_perspective.comp.h"

namespace volgraph {
namespace {

namespace cloud_aerial_perspective_shader = shaders::cloud_aerial_perspective_comp;

struct CloudAerialPerspectiveTable : PassTable {
  CloudAerialPerspectiveTable()
      : PassTable("cloud_aerial_perspective", PassKind::compute,
                  "The atmosphere's aerial perspective applied to the clouds at their depth: L·T_air + S_air·E·(1 − T_c).") {
    decl.needs = feature_bit(SceneFeature::clouds) | feature_bit(SceneFeature::atmosphere);
  }
  // Variants.
  VariantHandle mean_depth = variant("mean_depth", "one lookup at the clouds' transmittance-weighted mean distance (Hillaire 2016)");
  // Slots.
  SlotHandle clouds = input("clouds", ResourceKind::texture2d, Usage::sampled, "cloud_march.clouds: rgb radiance, a transmittance");
  SlotHandle distance = input("distance", ResourceKind::texture2d, Usage::sampled, "cloud_march.distance: the clouds' depth (m)");
  SlotHandle lookup = input("lookup", ResourceKind::buffer, Usage::uniform_read, "the volumes' frame (atmosphere_aerial_perspective.lookup)");
  SlotHandle aerial_scattering = input("aerial_scattering", ResourceKind::texture3d, Usage::sampled,
                                       "the air's in-scattering for a unit sun (atmosphere_aerial_perspective.aerial_scattering)");
  SlotHandle aerial_transmittance = input("aerial_transmittance", ResourceKind::texture3d, Usage::sampled,
                                          "the air's transmittance (atmosphere_aerial_perspective.aerial_transmittance)");
  SlotHandle clouds_through_air = output("through_air", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                                         "the clouds seen through the air: rgb radiance, a transmittance (unchanged)");
};

class CloudAerialPerspectiveExecution final : public PassExecution {
 public:
  explicit CloudAerialPerspectiveExecution(const CloudAerialPerspectiveTable& table) : t_(table) {}

  void setup(PassSetup& s) override {
    program_ = plumbing::create_compute_program(s.device, "cloud_aerial_perspective.comp");
    plumbing::check_wrapped_uniform_mirror<gpu::AerialLookup>(program_, cloud_aerial_perspective_shader::lookup, s.name() + " lookup");
  }

  void record(PassContext& c) override {
    namespace shader = cloud_aerial_perspective_shader;
    const rhi::BindGroupId group = c.bind_group(
        program_, {bind(shader::lookup, c.buffer(t_.lookup)), bind(shader::clouds, c.view(t_.clouds)),
                   bind(shader::cloud_distance, c.view(t_.distance)), bind(shader::aerial_scattering, c.view(t_.aerial_scattering)),
                   bind(shader::aerial_transmittance, c.view(t_.aerial_transmittance)),
                   bind(shader::trilinear, c.sampler(rhi::StockSampler::trilinear_clamp)),
                   bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
                   bind(shader::clouds_through_air, c.view(t_.clouds_through_air))});
    plumbing::dispatch(c.encoder, c.name(), program_, {group}, c.extent(t_.clouds_through_air));
  }

 private:
  const CloudAerialPerspectiveTable& t_;
  plumbing::ComputeProgram program_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CloudAerialPerspectiveTable, CloudAerialPerspectiveExecution);

}  // namespace volgraph
