// shaders/composite.comp on lavapipe, through the backend interface on each backend, against its CPU twin (physics/tonemap.h):
// every variant and several exposures, on a frame that is not a multiple of the
// workgroup size, with radiances from 0 to 1e4 (and a negative one, clamped to 0).
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "graph/access.h"
#include "tests/gpu/backends.h"

#include "physics/tonemap.h"
#include "passes/plumbing/programs.h"
#include "shaders/shader_library.h"

namespace volgraph::testing {
namespace {

constexpr uint32_t kCompositeShaderWidth = 13, kCompositeShaderHeight = 11;

float radiance_at(uint32_t x, uint32_t y, uint32_t c) {
  const float v = std::pow(10.0f, -3.0f + 7.0f * float(x + kCompositeShaderWidth * y) / float(kCompositeShaderWidth * kCompositeShaderHeight)) * (1.0f + 0.3f * float(c));
  return (x == 3 && y == 2) ? -1.0f : v;  // one negative radiance: clamped to 0
}

template <typename T>
std::span<const std::byte> bytes_of(const std::vector<T>& v) {
  return std::as_bytes(std::span(v));
}

// One run of the shader through the backend interface; returns the frame's texels.
// With `timestamps`, time stamps 0 and 1 bracket the dispatch.
std::vector<float> composite(rhi::Device& device, const std::vector<float>& radiance, float exposure, physics::ToneMap op,
                             rhi::QuerySetId timestamps = {}) {
  using namespace rhi;
  const TextureId input = device.create_texture({"radiance", ResourceKind::texture2d, Format::rgba32_float,
                                                 {kCompositeShaderWidth, kCompositeShaderHeight, 1}, texture_usage::sampled | texture_usage::copy_dst});
  const TextureId frame = device.create_texture({"frame", ResourceKind::texture2d, Format::rgba32_float,
                                                 {kCompositeShaderWidth, kCompositeShaderHeight, 1}, texture_usage::storage | texture_usage::copy_src});
  const BufferId params = device.create_buffer({"composite params", 16, buffer_usage::uniform | buffer_usage::copy_dst});
  const BufferId readback = device.create_buffer({"readback", uint64_t(kCompositeShaderWidth) * kCompositeShaderHeight * 16, buffer_usage::copy_dst});
  device.write_texture(input, bytes_of(radiance));
  struct {
    uint32_t size[2];
    float exposure_ev;
    int32_t tone_map_op;
  } block{{kCompositeShaderWidth, kCompositeShaderHeight}, exposure, int32_t(op)};
  device.write_buffer(params, 0, std::as_bytes(std::span(&block, 1)));

  const plumbing::ComputeProgram program = plumbing::create_compute_program(device, "composite.comp");
  BindGroupEntry e0, e1, e2, e3;
  e0.binding = 0;
  e0.view = device.create_view(input);
  e1.binding = 1;
  e1.sampler = device.create_sampler({"nearest"});
  e2.binding = 2;
  e2.view = device.create_view(frame);
  e3.binding = 3;
  e3.buffer = params;
  const BindGroupId group = device.create_bind_group({"composite", program.layouts[0], {e0, e1, e2, e3}});

  auto encoder = device.create_command_encoder("composite test");
  const AccessState sampled = access_state(Usage::sampled, PassKind::compute, ResourceKind::texture2d);
  const AccessState written = access_state(Usage::storage_write, PassKind::compute, ResourceKind::texture2d);
  const AccessState copied = access_state(Usage::copy_src, PassKind::transfer, ResourceKind::texture2d);
  const ResourceBarrier before[] = {{input, {}, Device::written_texture_state(), sampled}, {frame, {}, {}, written}};
  encoder->barrier(before);
  if (timestamps) encoder->write_timestamp(timestamps, 0);
  encoder->begin_compute_pass("composite");
  encoder->set_pipeline(program.pipeline);
  encoder->set_bind_group(0, group);
  const auto groups = program.groups_for({kCompositeShaderWidth, kCompositeShaderHeight, 1});
  encoder->dispatch(groups[0], groups[1]);
  encoder->end_compute_pass();
  if (timestamps) encoder->write_timestamp(timestamps, 1);
  const ResourceBarrier after[] = {{frame, {}, written, copied}};
  encoder->barrier(after);
  encoder->copy_texture_to_buffer(frame, readback, 0);
  device.submit(std::move(encoder));
  const std::vector<std::byte> raw = device.read_buffer(readback);
  std::vector<float> out(raw.size() / 4);
  std::memcpy(out.data(), raw.data(), raw.size());
  device.destroy(input);
  device.destroy(frame);
  return out;
}

class CompositeShader : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
};

TEST_P(CompositeShader, MatchesTheCpuTwinForEveryToneMap) {
  ASSERT_FALSE(shader_spirv("composite.comp").empty());
  rhi::Device& device = this->device();
  std::vector<float> radiance(size_t(kCompositeShaderWidth) * kCompositeShaderHeight * 4);
  for (uint32_t y = 0; y < kCompositeShaderHeight; ++y)
    for (uint32_t x = 0; x < kCompositeShaderWidth; ++x)
      for (uint32_t ch = 0; ch < 4; ++ch) radiance[4 * (x + kCompositeShaderWidth * y) + ch] = ch == 3 ? 1.0f : radiance_at(x, y, ch);
  for (const physics::ToneMap op : {physics::ToneMap::none, physics::ToneMap::aces, physics::ToneMap::reinhard}) {
    for (const float exposure : {-2.0f, 0.0f, 1.5f}) {
      const std::vector<float> result = composite(device, radiance, exposure, op);
      double worst = 0;
      for (uint32_t y = 0; y < kCompositeShaderHeight; ++y) {
        for (uint32_t x = 0; x < kCompositeShaderWidth; ++x) {
          const physics::Rgb in = {radiance_at(x, y, 0), radiance_at(x, y, 1), radiance_at(x, y, 2)};
          const physics::Rgb want = physics::tone_map(in, exposure, op);
          for (uint32_t ch = 0; ch < 3; ++ch) {
            const double got = result[4 * (x + kCompositeShaderWidth * y) + ch];
            // float32 evaluation of the same formula: relative error well under 1e-5.
            worst = std::max(worst, std::abs(got - want[ch]) / std::max(1e-3, std::abs(want[ch])));
          }
          EXPECT_EQ(result[4 * (x + kCompositeShaderWidth * y) + 3], 1.0f);
        }
      }
      EXPECT_LT(worst, 1e-5) << "tone map " << int(op) << " exposure " << exposure;
    }
  }
  EXPECT_EQ(device.info().backend, backend_name(backend()));
}

TEST_P(CompositeShader, TimestampsBracketTheDispatch) {
  rhi::Device& device = this->device();
  ASSERT_TRUE(device.has_timestamps()) << "lavapipe offers time stamps on both backends";
  const rhi::QuerySetId queries = device.create_timestamp_queries("composite", 2);
  const std::vector<float> radiance(size_t(kCompositeShaderWidth) * kCompositeShaderHeight * 4, 1.0f);
  for (int frame = 0; frame < 3; ++frame) {  // the query set is reusable frame after frame
    composite(device, radiance, 0.0f, physics::ToneMap::aces, queries);
    const std::vector<double> ns = device.read_timestamps(queries, 0, 2);
    EXPECT_GT(ns[1], ns[0]) << "frame " << frame;
    EXPECT_LT(ns[1] - ns[0], 1e9) << "a 13x11 dispatch under a second";
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, CompositeShader, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
