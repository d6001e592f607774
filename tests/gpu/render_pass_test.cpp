// Render passes through the backend interface on lavapipe, on each backend: DESIGN.md's orientation
// (NDC +y up, row 0 at the top), back-face culling of clockwise triangles, the depth
// test and additive blending, checked on read-back pixels with validation on.
#include <cstring>

#include <gtest/gtest.h>

#include "graph/access.h"
#include "shaders/shader_library.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

using namespace rhi;
constexpr uint32_t kRenderPassWidth = 16, kRenderPassHeight = 12;

struct Quad {
  float y0, y1;          // NDC, full width
  float z;               // depth in [0, 1]
  float color[4];
  bool clockwise = false;
};

class RenderPass : public OnEachBackend<> {
 protected:
  Backend backend() const override { return GetParam(); }
  void SetUp() override {
    OnEachBackend::SetUp();
    device_ = &device();
    layout_ = device_->create_bind_group_layout({"flat colour", {{0, shader_stage::fragment, BindingType::uniform_buffer}}});
    vertex_ = device_->create_shader_module("flat_color.vert", shader_spirv("flat_color.vert"));
    fragment_ = device_->create_shader_module("flat_color.frag", shader_spirv("flat_color.frag"));
  }

  // Draws the quads in order into a cleared frame; returns its RGBA texels, row 0 first.
  std::vector<float> render(const std::vector<Quad>& quads, CullMode cull, BlendMode blend, bool depth_test) {
    const TextureId color = device_->create_texture({"color", ResourceKind::texture2d, Format::rgba32_float,
                                                     {kRenderPassWidth, kRenderPassHeight, 1}, texture_usage::attachment | texture_usage::copy_src});
    const TextureId depth = device_->create_texture({"depth", ResourceKind::texture2d, Format::d32_float,
                                                     {kRenderPassWidth, kRenderPassHeight, 1}, texture_usage::attachment});
    const BufferId readback = device_->create_buffer({"readback", uint64_t(kRenderPassWidth) * kRenderPassHeight * 16, buffer_usage::copy_dst});
    RenderPipelineDesc pd;
    pd.label = "flat colour";
    pd.vertex_module = vertex_;
    pd.fragment_module = fragment_;
    pd.vertex_buffers = {{12, {{0, VertexFormat::float32x3, 0}}}};
    pd.colors = {{Format::rgba32_float, blend}};
    if (depth_test) pd.depth = {Format::d32_float, true, CompareFunction::less};
    pd.cull = cull;
    pd.layouts = {layout_};
    const RenderPipelineId pipeline = device_->create_render_pipeline(pd);

    std::vector<float> vertices;
    std::vector<BindGroupId> groups;
    for (const Quad& q : quads) {
      // Two triangles, counter-clockwise seen with +y up (or clockwise when asked).
      const float a[] = {-1, q.y0}, b[] = {1, q.y0}, c[] = {1, q.y1}, d[] = {-1, q.y1};
      const float* order[] = {a, b, c, a, c, d};
      const float* reversed[] = {a, c, b, a, d, c};
      for (const float* p : q.clockwise ? reversed : order) vertices.insert(vertices.end(), {p[0], p[1], q.z});
      const BufferId params = device_->create_buffer({"colour", 16, buffer_usage::uniform});
      device_->write_buffer(params, 0, std::as_bytes(std::span(q.color)));
      BindGroupEntry e;
      e.buffer = params;
      groups.push_back(device_->create_bind_group({"colour", layout_, {e}}));
    }
    const BufferId vbo = device_->create_buffer({"quads", std::max<size_t>(4, vertices.size() * 4), buffer_usage::vertex});
    if (!vertices.empty()) device_->write_buffer(vbo, 0, std::as_bytes(std::span(vertices)));

    auto enc = device_->create_command_encoder("render pass test");
    const AccessState target = access_state(Usage::color_attachment, PassKind::graphics, ResourceKind::texture2d);
    const AccessState depth_target = access_state(Usage::depth_attachment, PassKind::graphics, ResourceKind::texture2d);
    const ResourceBarrier before[] = {{color, {}, {}, target}, {depth, {}, {}, depth_target}};
    enc->barrier(before);
    RenderPassDesc rp;
    rp.label = "quads";
    rp.colors = {{device_->create_view(color), LoadOp::clear, {0, 0, 0, 0}}};
    if (depth_test) rp.depth = {device_->create_view(depth), LoadOp::clear, 1.0f, false};
    enc->begin_render_pass(rp);
    enc->set_pipeline(pipeline);
    enc->set_vertex_buffer(0, vbo);
    for (size_t i = 0; i < quads.size(); ++i) {
      enc->set_bind_group(0, groups[i]);
      enc->draw(6, 1, uint32_t(6 * i));
    }
    enc->end_render_pass();
    const ResourceBarrier after[] = {{color, {}, target, access_state(Usage::copy_src, PassKind::transfer, ResourceKind::texture2d)}};
    enc->barrier(after);
    enc->copy_texture_to_buffer(color, readback, 0);
    device_->submit(std::move(enc));
    const auto raw = device_->read_buffer(readback);
    std::vector<float> texels(raw.size() / 4);
    std::memcpy(texels.data(), raw.data(), raw.size());
    return texels;
  }

  static float red(const std::vector<float>& texels, uint32_t x, uint32_t y) { return texels[4 * (y * kRenderPassWidth + x)]; }

  rhi::Device* device_ = nullptr;
  BindGroupLayoutId layout_;
  ShaderModuleId vertex_, fragment_;
};

TEST_P(RenderPass, PositiveNdcYIsTheTopOfTheImage) {
  const auto t = render({{0.0f, 1.0f, 0.5f, {1, 0, 0, 1}}}, CullMode::back, BlendMode::replace, true);
  for (uint32_t y = 0; y < kRenderPassHeight; ++y) {
    for (uint32_t x = 0; x < kRenderPassWidth; ++x) {
      // Pixel row j's centre is at NDC y = 1 − (j + 0.5)/H·2: rows 0–5 lie above y = 0.
      EXPECT_EQ(red(t, x, y), y < kRenderPassHeight / 2 ? 1.0f : 0.0f) << "pixel " << x << ", " << y;
    }
  }
}

TEST_P(RenderPass, ClockwiseTrianglesAreBackFacesAndCulled) {
  EXPECT_EQ(red(render({{-1, 1, 0.5f, {1, 0, 0, 1}, true}}, CullMode::back, BlendMode::replace, true), 8, 6), 0.0f);
  EXPECT_EQ(red(render({{-1, 1, 0.5f, {1, 0, 0, 1}, true}}, CullMode::none, BlendMode::replace, true), 8, 6), 1.0f);
  EXPECT_EQ(red(render({{-1, 1, 0.5f, {1, 0, 0, 1}, false}}, CullMode::back, BlendMode::replace, true), 8, 6), 1.0f);
}

TEST_P(RenderPass, TheNearerSurfaceWinsWhateverTheDrawOrder) {
  const Quad far{-1, 1, 0.7f, {0.25f, 0, 0, 1}}, near{-1, 1, 0.3f, {0.75f, 0, 0, 1}};
  EXPECT_EQ(red(render({far, near}, CullMode::back, BlendMode::replace, true), 3, 3), 0.75f);
  EXPECT_EQ(red(render({near, far}, CullMode::back, BlendMode::replace, true), 3, 3), 0.75f);
}

TEST_P(RenderPass, AdditiveBlendingSums) {
  const Quad a{-1, 1, 0.5f, {0.25f, 0, 0, 0}}, b{-1, 1, 0.5f, {0.5f, 0, 0, 0}};
  EXPECT_EQ(red(render({a, b}, CullMode::none, BlendMode::additive, false), 5, 9), 0.75f);
}

// Premultiplied under, front to back (dst + src·(1 − dst α)), is over, back to front: a front
// layer (0.25, α 0.5) and a back one (0.5, α 0.5) make 0.25 + 0.5 · 0.5 either way, exactly.
TEST_P(RenderPass, PremultipliedUnderFrontToBackIsOverBackToFront) {
  const Quad front{-1, 1, 0.5f, {0.25f, 0, 0, 0.5f}}, back{-1, 1, 0.5f, {0.5f, 0, 0, 0.5f}};
  EXPECT_EQ(red(render({front, back}, CullMode::none, BlendMode::premultiplied_under, false), 5, 9), 0.5f);
  EXPECT_EQ(red(render({back, front}, CullMode::none, BlendMode::premultiplied_over, false), 5, 9), 0.5f);
}

// In-stream buffer updates are ordered like any transfer write: update, barrier, copy.
TEST_P(RenderPass, UpdateBufferLandsBeforeTheCopyAfterIt) {
  const BufferId a = device_->create_buffer({"a", 64, buffer_usage::copy_src | buffer_usage::copy_dst});
  const BufferId b = device_->create_buffer({"b", 64, buffer_usage::copy_dst});
  std::vector<uint32_t> words(16);
  for (uint32_t i = 0; i < 16; ++i) words[i] = 0xC0DE0000u + i;
  auto enc = device_->create_command_encoder("update");
  enc->update_buffer(a, 0, std::as_bytes(std::span(words)));
  const AccessState written = access_state(Usage::copy_dst, PassKind::transfer, ResourceKind::buffer);
  const ResourceBarrier between[] = {{{}, a, written, access_state(Usage::copy_src, PassKind::transfer, ResourceKind::buffer)}};
  enc->barrier(between);
  enc->copy_buffer_to_buffer(a, b, 64);
  device_->submit(std::move(enc));
  const auto raw = device_->read_buffer(b);
  std::vector<uint32_t> got(16);
  std::memcpy(got.data(), raw.data(), 64);
  EXPECT_EQ(got, words);
}

INSTANTIATE_TEST_SUITE_P(Backends, RenderPass, ::testing::ValuesIn(gpu_backends()), backend_test_name);

}  // namespace
}  // namespace volgraph::testing
