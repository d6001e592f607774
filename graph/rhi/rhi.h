// The backend interface passes talk to. Shaped like WebGPU (the stricter of the two
// APIs), in volgraph's own terms, so that the WebGPU backend maps it one to one and the
// Vulkan backend fills in what WebGPU does implicitly. Barriers are explicit and in the
// plan's vocabulary (AccessState): the executor hands over the plan's transitions as they
// are; WebGPU, which tracks usage itself, ignores them.
// Coordinates follow WebGPU: in normalised device coordinates +y is up, depth is in
// [0, 1], and framebuffer row 0 is the top row (DESIGN.md's pixel convention).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <tuple>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "graph/rhi/types.h"

namespace volgraph {
struct Graph;
}

namespace volgraph::rhi {

class GraphResourceSet;  // graph/rhi/graph_resource_set.h

// Typed handles owned by the Device; 0 is "none".
template <typename Tag>
struct Handle {
  uint32_t id = 0;
  explicit operator bool() const { return id != 0; }
  friend bool operator==(Handle, Handle) = default;
};
using BufferId = Handle<struct BufferTag>;
using TextureId = Handle<struct TextureTag>;
using TextureViewId = Handle<struct TextureViewTag>;
using SamplerId = Handle<struct SamplerTag>;
using ShaderModuleId = Handle<struct ShaderModuleTag>;
using BindGroupLayoutId = Handle<struct BindGroupLayoutTag>;
using BindGroupId = Handle<struct BindGroupTag>;
using ComputePipelineId = Handle<struct ComputePipelineTag>;
using RenderPipelineId = Handle<struct RenderPipelineTag>;
using QuerySetId = Handle<struct QuerySetTag>;

namespace buffer_usage {  // as WGPUBufferUsage
constexpr uint32_t copy_src = 1u << 0;
constexpr uint32_t copy_dst = 1u << 1;
constexpr uint32_t uniform = 1u << 2;
constexpr uint32_t storage = 1u << 3;
constexpr uint32_t vertex = 1u << 4;
constexpr uint32_t index = 1u << 5;
}  // namespace buffer_usage

namespace texture_usage {  // as WGPUTextureUsage
constexpr uint32_t copy_src = 1u << 0;
constexpr uint32_t copy_dst = 1u << 1;
constexpr uint32_t sampled = 1u << 2;
constexpr uint32_t storage = 1u << 3;
constexpr uint32_t attachment = 1u << 4;
}  // namespace texture_usage

namespace shader_stage {
constexpr uint32_t vertex = 1u << 0;
constexpr uint32_t fragment = 1u << 1;
constexpr uint32_t compute = 1u << 2;
}  // namespace shader_stage

struct BufferDesc {
  std::string label;
  uint64_t size = 0;
  uint32_t usage = 0;
};

struct TextureDesc {
  std::string label;
  ResourceKind kind = ResourceKind::texture2d;
  Format format = Format::rgba16_float;
  Extent size{};
  uint32_t usage = 0;
  uint32_t mip_levels = 1;  // level i is max(1, size >> i)
};

enum class Filter : uint8_t { nearest, linear };
enum class AddressMode : uint8_t { clamp_to_edge, repeat, mirror_repeat };

// The samplers passes share (Device::stock_sampler): filter, then wrap mode.
enum class StockSampler : uint8_t { nearest_clamp, linear_clamp, trilinear_clamp, linear_repeat, count };

struct SamplerDesc {
  std::string label;
  Filter filter = Filter::nearest;      // magnification and minification
  Filter mip_filter = Filter::nearest;  // between mip levels
  AddressMode address_u = AddressMode::clamp_to_edge;
  AddressMode address_v = AddressMode::clamp_to_edge;
  AddressMode address_w = AddressMode::clamp_to_edge;
};

enum class BindingType : uint8_t { uniform_buffer, storage_buffer, read_only_storage_buffer, sampled_texture, sampler, storage_texture };

enum class StorageAccess : uint8_t { read_write, read_only, write_only };

struct LayoutEntry {
  uint32_t binding = 0;
  uint32_t visibility = shader_stage::compute;
  BindingType type = BindingType::uniform_buffer;
  ResourceKind texture_kind = ResourceKind::texture2d;  // sampled and storage textures
  // A texture_cube's faces as a 2D array (image2DArray, texture2DArray: storage writes, a
  // face per layer) rather than the cube (samplerCube).
  bool cube_faces = false;
  Format storage_format = Format::undefined;            // storage textures
  // Sampled textures and samplers, as the shaders use them (reflection): true when
  // some shader samples through them (texture(), textureLod …), false when the texture
  // is only fetched or queried (texelFetch, textureSize). WebGPU needs it: a filtered
  // texture must have a filterable format and its sampler may filter; a fetched one
  // may hold any float format (32-bit float, depth) and its sampler must not filter.
  bool filtered = false;
  StorageAccess storage_access = StorageAccess::read_write;  // storage textures
};

struct BindGroupLayoutDesc {
  std::string label;
  std::vector<LayoutEntry> entries;
};

// One resource per binding: a buffer range, a texture view, or a sampler.
struct BindGroupEntry {
  uint32_t binding = 0;
  BufferId buffer;
  uint64_t offset = 0;
  uint64_t size = 0;  // 0: to the end
  TextureViewId view;
  SamplerId sampler;

  static BindGroupEntry of(uint32_t binding, BufferId buffer) { return {binding, buffer, 0, 0, {}, {}}; }
  static BindGroupEntry of(uint32_t binding, TextureViewId view) { return {binding, {}, 0, 0, view, {}}; }
  static BindGroupEntry of(uint32_t binding, SamplerId sampler) { return {binding, {}, 0, 0, {}, sampler}; }
};

struct BindGroupDesc {
  std::string label;
  BindGroupLayoutId layout;
  std::vector<BindGroupEntry> entries;
};

struct ComputePipelineDesc {
  std::string label;
  ShaderModuleId module;
  std::string entry_point = "main";
  std::vector<BindGroupLayoutId> layouts;  // set i = layouts[i]
};

enum class VertexFormat : uint8_t { float32x2, float32x3, float32x4 };

struct VertexAttribute {
  uint32_t location = 0;
  VertexFormat format = VertexFormat::float32x3;
  uint32_t offset = 0;
};

struct VertexBufferLayout {
  uint32_t stride = 0;
  std::vector<VertexAttribute> attributes;
};

enum class CompareFunction : uint8_t { never, less, less_equal, greater, greater_equal, equal, not_equal, always };
enum class CullMode : uint8_t { none, front, back };
// additive: src + dst (light volumes, accumulation); multiply: dst × src (transmittance);
// source_plus_dest_times_source1: src0 + dst × src1, the fragment's second output (index 1)
// the destination's factor: a layer's radiance over its transmittance in one draw, on a
// device with Device::has_dual_source_blending().
// premultiplied_over: src + dst × (1 − src alpha), Porter & Duff's over for premultiplied
// colour (slices blended back to front). premultiplied_under: dst + src × (1 − dst alpha), the
// same composite drawn front to back (half-angle slices whose light comes from behind the eye).
enum class BlendMode : uint8_t { replace, additive, multiply, source_plus_dest_times_source1, premultiplied_over, premultiplied_under };
enum class IndexFormat : uint8_t { uint16, uint32 };
enum class LoadOp : uint8_t { clear, load };

struct ColorTargetState {
  Format format = Format::rgba16_float;
  BlendMode blend = BlendMode::replace;
};

struct DepthStencilState {
  Format format = Format::undefined;  // undefined: no depth attachment
  bool write = true;
  CompareFunction compare = CompareFunction::less;
  float bias_constant = 0;  // in units of the format's minimum resolvable difference
  float bias_slope = 0;
};

struct RenderPipelineDesc {
  std::string label;
  ShaderModuleId vertex_module;
  std::string vertex_entry = "main";
  ShaderModuleId fragment_module;  // none: depth only
  std::string fragment_entry = "main";
  std::vector<VertexBufferLayout> vertex_buffers;
  std::vector<ColorTargetState> colors;
  DepthStencilState depth;
  CullMode cull = CullMode::none;
  bool front_counter_clockwise = true;
  std::vector<BindGroupLayoutId> layouts;
};

struct ColorAttachment {
  TextureViewId view;
  LoadOp load = LoadOp::clear;
  float clear[4] = {0, 0, 0, 0};
};

struct DepthAttachment {
  TextureViewId view;
  LoadOp load = LoadOp::clear;
  float clear = 1.0f;
  bool read_only = false;  // depth test only (the depth_read usage)
};

struct RenderPassDesc {
  std::string label;
  std::vector<ColorAttachment> colors;
  DepthAttachment depth;  // view none: no depth
};

// A transition of one texture or buffer, in the plan's terms; neither: all memory
// (the plan's --serialize barriers).
struct ResourceBarrier {
  TextureId texture;
  BufferId buffer;
  AccessState from{};  // layout undefined: contents discarded
  AccessState to{};
};

struct AdapterInfo {
  std::string backend;  // "vulkan", "webgpu"
  std::string device;
  std::string driver;
};

class CommandEncoder {
 public:
  virtual ~CommandEncoder() = default;

  // Labels a stretch of commands (a pass) for validation messages and frame debuggers.
  virtual void push_debug_group(std::string_view label) = 0;
  virtual void pop_debug_group() = 0;

  // Transitions before the next command; all given together are batched.
  virtual void barrier(std::span<const ResourceBarrier> barriers) = 0;

  virtual void begin_compute_pass(std::string_view label) = 0;
  virtual void set_pipeline(ComputePipelineId pipeline) = 0;
  virtual void dispatch(uint32_t x, uint32_t y = 1, uint32_t z = 1) = 0;
  virtual void end_compute_pass() = 0;

  // The viewport and scissor cover the attachments (all of one size).
  virtual void begin_render_pass(const RenderPassDesc& desc) = 0;
  virtual void set_pipeline(RenderPipelineId pipeline) = 0;
  virtual void set_vertex_buffer(uint32_t slot, BufferId buffer, uint64_t offset = 0) = 0;
  virtual void set_index_buffer(BufferId buffer, IndexFormat format, uint64_t offset = 0) = 0;
  virtual void draw(uint32_t vertex_count, uint32_t instance_count = 1, uint32_t first_vertex = 0) = 0;
  virtual void draw_indexed(uint32_t index_count, uint32_t instance_count = 1, uint32_t first_index = 0,
                            int32_t base_vertex = 0) = 0;
  virtual void end_render_pass() = 0;

  // For the pipeline set last (compute or render).
  virtual void set_bind_group(uint32_t index, BindGroupId group) = 0;

  // GPU time stamps (when the device has them: Device::has_timestamps()), written when
  // all work recorded before has finished; Device::read_timestamps turns them into ns.
  virtual void write_timestamp(QuerySetId queries, uint32_t index) = 0;

  // Writes up to 64 KiB into a buffer (made with copy_dst) at this point of the
  // command stream: per-pass constants in graph buffers. A transfer write.
  virtual void update_buffer(BufferId buffer, uint64_t offset, std::span<const std::byte> data) = 0;

  // Whole-texture copies, rows tightly packed in the buffer.
  virtual void copy_buffer_to_texture(BufferId source, uint64_t offset, TextureId destination) = 0;
  // One mip level (`mip_level`; 0: the texture without a chain) into the buffer at `offset`, rows tightly packed.
  virtual void copy_texture_to_buffer(TextureId source, BufferId destination, uint64_t offset, uint32_t mip_level = 0) = 0;
  virtual void copy_texture_to_texture(TextureId source, TextureId destination) = 0;  // same size and format
  // From the source's start to `destination_offset` (read-backs gather several resources).
  virtual void copy_buffer_to_buffer(BufferId source, BufferId destination, uint64_t size,
                                     uint64_t destination_offset = 0) = 0;
};

class Device {
 public:
  virtual ~Device() = default;
  virtual AdapterInfo info() const = 0;

  // The bind group of desc.layout holding desc.entries: made on first request, then the
  // same group for the same layout and entries (the label is the first request's).
  // Passes ask for their groups this way at record time instead of keeping them.
  BindGroupId cached_bind_group(const BindGroupDesc& desc);
  // One sampler of each StockSampler kind, made on first use.
  SamplerId stock_sampler(StockSampler which);
  // A sampled texture's view by its source's key (a file and its image): made by `make`
  // on the first request, then the same view for the device's life, so the passes that
  // draw one scene (scene, shadow_map, translucency) and the frames after decode and
  // upload each image once.
  TextureViewId cached_texture_view(const std::string& key, const std::function<TextureViewId()>& make);
  // Shader modules, bind group layouts and pipelines by their content, as Dawn and
  // Granite keep them: made on the first request (with its label), then the same object
  // for the device's life, so every render and frame on one device compiles each
  // pipeline once (lavapipe's and Tint's compiles were most of a test's time).
  ShaderModuleId cached_shader_module(std::string_view label, std::span<const uint32_t> spirv);
  // Shaders replaced at run time (`view`'s shader hot reload): programs made after
  // replace_shader use `spirv` in place of the embedded shader of that name (the caches
  // above key on content, so new modules and pipelines follow); restore_shader undoes it.
  void replace_shader(const std::string& name, std::vector<uint32_t> spirv) { replaced_shaders_[name] = std::move(spirv); }
  void restore_shader(const std::string& name) { replaced_shaders_.erase(name); }
  // The replacement of `name`; empty where there is none.
  std::span<const uint32_t> replaced_shader(std::string_view name) const {
    const auto it = replaced_shaders_.find(name);
    return it == replaced_shaders_.end() ? std::span<const uint32_t>{} : std::span<const uint32_t>(it->second);
  }
  BindGroupLayoutId cached_bind_group_layout(const BindGroupLayoutDesc& desc);
  ComputePipelineId cached_compute_pipeline(const ComputePipelineDesc& desc);
  RenderPipelineId cached_render_pipeline(const RenderPipelineDesc& desc);

  virtual BufferId create_buffer(const BufferDesc& desc) = 0;
  virtual TextureId create_texture(const TextureDesc& desc) = 0;
  virtual TextureViewId create_view(TextureId texture) = 0;  // the whole texture (every mip level), its own format
  virtual SamplerId create_sampler(const SamplerDesc& desc) = 0;
  virtual ShaderModuleId create_shader_module(std::string_view label, std::span<const uint32_t> spirv) = 0;
  virtual BindGroupLayoutId create_bind_group_layout(const BindGroupLayoutDesc& desc) = 0;
  virtual BindGroupId create_bind_group(const BindGroupDesc& desc) = 0;
  virtual ComputePipelineId create_compute_pipeline(const ComputePipelineDesc& desc) = 0;
  virtual RenderPipelineId create_render_pipeline(const RenderPipelineDesc& desc) = 0;
  virtual bool has_timestamps() const = 0;
  // Whether pipelines may blend with the fragment's second output
  // (BlendMode::source_plus_dest_times_source1): Vulkan dualSrcBlend, WebGPU
  // "dual-source-blending" where the shader path expresses it.
  virtual bool has_dual_source_blending() const = 0;
  virtual QuerySetId create_timestamp_queries(std::string_view label, uint32_t count) = 0;
  // Nanoseconds of each time stamp in [first, first + count), from an arbitrary origin
  // (waits for everything submitted).
  virtual std::vector<double> read_timestamps(QuerySetId queries, uint32_t first, uint32_t count) = 0;
  // Frees the memory now (as WebGPU's destroy()); the handle must not be used again.
  virtual void destroy(BufferId buffer) = 0;
  virtual void destroy(TextureId texture) = 0;

  // Queue writes, done before anything submitted later reads: a buffer written this way
  // is ready for any use; a texture is left ready to be sampled by any shader
  // (`written_texture_state()`), as WebGPU's writeTexture leaves it.
  virtual void write_buffer(BufferId buffer, uint64_t offset, std::span<const std::byte> data) = 0;
  // One mip level's texels, rows tightly packed.
  virtual void write_texture(TextureId texture, std::span<const std::byte> texels, uint32_t mip_level = 0) = 0;
  static AccessState written_texture_state() {
    return {stage::vertex_shader | stage::fragment_shader | stage::compute_shader, access::shader_sampled_read, Layout::shader_read_only};
  }

  virtual std::unique_ptr<GraphResourceSet> create_graph_resources(const Graph& graph) = 0;

  virtual std::unique_ptr<CommandEncoder> create_command_encoder(std::string_view label) = 0;
  // Runs the commands and waits for them.
  virtual void submit(std::unique_ptr<CommandEncoder> commands) = 0;
  // The contents of a buffer created with copy_dst (waits for everything submitted).
  virtual std::vector<std::byte> read_buffer(BufferId buffer) = 0;

 private:
  struct BindGroupKey {
    BindGroupLayoutId layout;
    std::vector<std::array<uint64_t, 6>> entries;  // binding, buffer, offset, size, view, sampler
    friend bool operator<(const BindGroupKey& a, const BindGroupKey& b) {
      return std::tie(a.layout.id, a.entries) < std::tie(b.layout.id, b.entries);
    }
  };
  std::map<BindGroupKey, BindGroupId> bind_groups_;
  std::array<SamplerId, size_t(StockSampler::count)> stock_samplers_{};
  std::map<std::string, TextureViewId, std::less<>> texture_views_;
  // Keyed by the bytes of what defines the object (device_caches.cpp's content_key).
  std::map<std::string, ShaderModuleId, std::less<>> shader_modules_;
  std::map<std::string, std::vector<uint32_t>, std::less<>> replaced_shaders_;
  std::map<std::string, BindGroupLayoutId, std::less<>> bind_group_layouts_;
  std::map<std::string, ComputePipelineId, std::less<>> compute_pipelines_;
  std::map<std::string, RenderPipelineId, std::less<>> render_pipelines_;
};

}  // namespace volgraph::rhi
