// cloud_temporal: the clouds' temporal upsampling (Schneider & Vos 2015, Horizon Zero
// Dawn). cloud_march with update_block B marches one pixel of each B × B block per frame
// (passes/clouds/cloud_blocks.h: the Bayer order); this pass rebuilds the full-resolution
// images: the pixel marched this frame takes the new value, the others the last frame's
// result reprojected at the clouds' depth (the march's `distance`: the opacity-weighted
// mean distance), not the scene's — a sky pixel reprojected at the far plane, as
// pixel_temporal does, ghosts when the camera moves. Off the last frame's view, and on the
// first frame, the small image upsampled (its block's texel). With B = 1 every pixel is
// marched and blended with its reprojected history (pixel_temporal's moving average).
// B is read from the march that makes the input (its update_block), never a copy that may
// disagree. Shader: shaders/cloud_temporal.comp.
#include <array>

#include "graph/execute/pass_execution.h"
#include "passes/clouds/cloud_blocks.h"
#include "passes/fog/temporal.h"
#include "passes/register_pass.h"
#include "shaders/bindings/cloud_temporal.comp.h"
#include "shaders/include/cloud_temporal_params.h"

namespace volgraph {
namespace {

namespace cloud_temporal_shader = shaders::cloud_temporal_comp;

struct CloudTemporalTable : fog::TemporalTable {
  CloudTemporalTable()
      : TemporalTable("cloud_temporal",
                      "The clouds' temporal upsampling: cloud_march's one pixel per block each frame, the rest reprojected at "
                      "the clouds' depth.") {
    decl.needs = feature_bit(SceneFeature::clouds);
  }
  VariantHandle upsampled =
      variant("upsampled", "the marched pixel new, the rest the last frame's result read where its camera saw the clouds");
  ParamHandle<bool> at_cloud_depth =
      flag("at_cloud_depth", true, "reproject each pixel's point at the clouds' depth (the march's distance); off: at the far plane");
  // Slots (alpha and reproject are TemporalTable's).
  SlotHandle marched_clouds = input("marched_clouds", ResourceKind::texture2d, Usage::sampled,
                                    "cloud_march.clouds: rgb radiance, a transmittance, one texel per update_block block");
  SlotHandle marched_distance = input("marched_distance", ResourceKind::texture2d, Usage::sampled, "cloud_march.distance: the clouds' depth (m)");
  SlotHandle clouds = output("clouds", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float, SizeSpec::of_output(),
                             "the clouds at full resolution: rgb in-scattered radiance, a transmittance");
  SlotHandle transmittance = output("transmittance", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                    SizeSpec::of_output(), "the transmittance in rgb (fog_apply's fog_transmittance); a: frames blended");
  SlotHandle clouds_history = history("clouds_history", clouds, "the last frame's clouds");
  SlotHandle transmittance_history = history("transmittance_history", transmittance, "the last frame's transmittance and frame count");
};

class CloudTemporalExecution final : public fog::TemporalExecution {
 public:
  explicit CloudTemporalExecution(const CloudTemporalTable& table)
      : TemporalExecution(table, "cloud_temporal.comp", table.clouds, cloud_temporal_shader::params.binding), t_(table) {}

 private:
  void setup_blocks(PassSetup& s) override {
    frame_ = s.device.create_buffer({"cloud_temporal frame", sizeof(gpu::FogFrame), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
    block_ = s.device.create_buffer(
        {"cloud_temporal block", sizeof(gpu::CloudTemporalBlock), rhi::buffer_usage::uniform | rhi::buffer_usage::copy_dst});
  }

  // This frame's camera (a frame block; its grid unused) and the march's block and pixel.
  void write_blocks(PassContext& c) override {
    fog::FogFrameInputs in;
    in.grid = c.extent(t_.clouds);
    in.range = {c.scene->camera.near, c.scene->camera.far, physics::FroxelDistribution::linear};
    in.jitter = false;
    const gpu::FogFrame frame = fog::make_fog_frame(c, c.frame, in, lighting_);
    c.device.write_buffer(frame_, 0, std::as_bytes(std::span(&frame, 1)));
    // The march's own update_block: the blocks this pass rebuilds are the ones it marched.
    const int block = int(c.producer_param(t_.marched_clouds, "update_block"));
    const std::array<int32_t, 2> offset = clouds::marched_offset(c.frame, block);
    gpu::CloudTemporalBlock b{};
    b.block[0] = block, b.block[1] = offset[0], b.block[2] = offset[1];
    b.depth[0] = c.param(t_.at_cloud_depth) ? 1.0f : 0.0f;
    c.device.write_buffer(block_, 0, std::as_bytes(std::span(&b, 1)));
  }

  std::vector<rhi::BoundResource> entries(PassContext& c) override {
    namespace shader = cloud_temporal_shader;
    return {bind(shader::frame, frame_),
            bind(shader::marched_clouds, c.view(t_.marched_clouds)),
            bind(shader::marched_distance, c.view(t_.marched_distance)),
            bind(shader::clouds_history, c.view(t_.clouds_history)),
            bind(shader::transmittance_history, c.view(t_.transmittance_history)),
            bind(shader::nearest, c.sampler(rhi::StockSampler::nearest_clamp)),
            bind(shader::bilinear, c.sampler(rhi::StockSampler::linear_clamp)),
            bind(shader::clouds, c.view(t_.clouds)),
            bind(shader::cloud_transmittance, c.view(t_.transmittance)),
            bind(shader::params, params()),
            bind(shader::b, block_)};
  }

  const CloudTemporalTable& t_;
  rhi::BufferId frame_, block_;
  plumbing::SceneLighting lighting_;
};

}  // namespace

VOLGRAPH_REGISTER_PASS(CloudTemporalTable, CloudTemporalExecution);

}  // namespace volgraph
