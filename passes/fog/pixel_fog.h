// What the per-pixel fog techniques (depth_fog, height_fog, analytic_fog) share: their
// slots — the scene's depth in; in-scattered radiance and transmittance out, rgba16f
// storage images at the frame's size (overridable: lower resolutions are upsampled by
// fog_apply) — and one compute dispatch over those images with the fog frame block
// (fog_frame.h, packed here: no froxel_voxelize is needed), the depth and the
// technique's own parameter block. Shaders include shaders/include/pixel_fog.glsl.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "graph/execute/pass_execution.h"
#include "graph/pass_decl.h"
#include "graph/scene/scene.h"
#include "passes/plumbing/scene_lighting.h"
#include "passes/plumbing/programs.h"

namespace volgraph::fog {

// The techniques' shared slots, in this order; a technique's table derives from it and
// adds its variants and parameters.
struct PixelFogTable : PassTable {
  PixelFogTable(std::string name, std::string doc) : PassTable(std::move(name), PassKind::compute, std::move(doc)) {
    decl.needs = feature_bit(SceneFeature::medium);
  }
  SlotHandle depth = input("depth", ResourceKind::texture2d, Usage::sampled, "the scene's depth (d32; 1 where nothing was drawn)",
                           {.format = Format::d32_float});
  SlotHandle fog_scattering = output("fog_scattering", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                     SizeSpec::of_output(), "in-scattered radiance toward the camera, rgb (W/(m²·sr))",
                                     {.size_overridable = true});
  SlotHandle fog_transmittance = output("fog_transmittance", ResourceKind::texture2d, Usage::storage_write, Format::rgba16_float,
                                        SizeSpec::of_output(),
                                        "transmittance from the camera to the surface (or the far plane), rgb",
                                        {.size_overridable = true});
};

// What a technique hands its shader: the bytes of its Params block (binding 5; empty: it
// has none) with the offsets of that mirror struct's members (checked against the
// shader's block at setup), and the radiance the media scatter uniformly (the frame
// block's ambient).
struct PixelFogInputs {
  std::vector<std::byte> params;
  std::vector<uint64_t> params_offsets;
  Vec3 ambient{0, 0, 0};

  // Inputs whose Params block is `block`, a mirror struct (Block::offsets()).
  template <typename Block>
  static PixelFogInputs with_params(const Block& block, Vec3 ambient) {
    const auto bytes = std::as_bytes(std::span(&block, 1));
    if constexpr (requires { Block::offsets(); }) {
      const auto offsets = Block::offsets();
      return {{bytes.begin(), bytes.end()}, {offsets.begin(), offsets.end()}, ambient};
    } else {  // a struct written once (gpu_struct.h), the one member of its block: laid out at compile time
      return {{bytes.begin(), bytes.end()}, {0}, ambient};
    }
  }
};
using PixelFogInputsOf = std::function<PixelFogInputs(const PassSetup& s)>;

// The techniques' execution: `shader` dispatched over the two images, with the inputs
// `inputs_of` gives at setup (they do not change between frames). A technique's
// execution derives from it to name its shader and inputs.
class PixelFogExecution : public PassExecution {
 public:
  PixelFogExecution(const PixelFogTable& table, std::string shader, PixelFogInputsOf inputs_of)
      : t_(table), shader_(std::move(shader)), inputs_of_(std::move(inputs_of)) {}

  void setup(PassSetup& s) override;
  void record(PassContext& c) override;

 private:
  const PixelFogTable& t_;
  std::string shader_;
  PixelFogInputsOf inputs_of_;
  plumbing::ComputeProgram program_;
  rhi::BufferId frame_, params_;
  plumbing::SceneLighting lighting_;
};


}  // namespace volgraph::fog
