// Conversions from volgraph's terms to WebGPU's (formats.h).
#include "graph/rhi/webgpu/formats.h"

namespace volgraph::webgpu {

wgpu::TextureFormat to_wgpu(Format format) {
  using F = wgpu::TextureFormat;
  switch (format) {
    case Format::undefined: return F::Undefined;
    case Format::r8_unorm: return F::R8Unorm;
    case Format::rgba8_unorm: return F::RGBA8Unorm;
    case Format::rgba8_srgb: return F::RGBA8UnormSrgb;
    case Format::r16_float: return F::R16Float;
    case Format::rg16_float: return F::RG16Float;
    case Format::rgba16_float: return F::RGBA16Float;
    case Format::r32_float: return F::R32Float;
    case Format::rg32_float: return F::RG32Float;
    case Format::rgba32_float: return F::RGBA32Float;
    case Format::r11g11b10_float: return F::RG11B10Ufloat;
    case Format::r32_uint: return F::R32Uint;
    case Format::d16_unorm: return F::Depth16Unorm;
    case Format::d32_float: return F::Depth32Float;
  }
  return F::Undefined;
}

wgpu::TextureDimension dimension_of(ResourceKind kind) {
  return kind == ResourceKind::texture3d ? wgpu::TextureDimension::e3D : wgpu::TextureDimension::e2D;
}

wgpu::TextureViewDimension view_dimension_of(ResourceKind kind, bool cube_faces) {
  if (kind == ResourceKind::texture3d) return wgpu::TextureViewDimension::e3D;
  if (kind != ResourceKind::texture_cube) return wgpu::TextureViewDimension::e2D;
  return cube_faces ? wgpu::TextureViewDimension::e2DArray : wgpu::TextureViewDimension::Cube;
}

wgpu::TextureAspect copy_aspect(Format format) {
  return format_info(format).is_depth ? wgpu::TextureAspect::DepthOnly : wgpu::TextureAspect::All;
}

wgpu::TextureUsage texture_usage(uint32_t rhi_usage) {
  wgpu::TextureUsage out = wgpu::TextureUsage::None;
  if (rhi_usage & rhi::texture_usage::copy_src) out |= wgpu::TextureUsage::CopySrc;
  if (rhi_usage & rhi::texture_usage::copy_dst) out |= wgpu::TextureUsage::CopyDst;
  if (rhi_usage & rhi::texture_usage::sampled) out |= wgpu::TextureUsage::TextureBinding;
  if (rhi_usage & rhi::texture_usage::storage) out |= wgpu::TextureUsage::StorageBinding;
  if (rhi_usage & rhi::texture_usage::attachment) out |= wgpu::TextureUsage::RenderAttachment;
  return out;
}

wgpu::BufferUsage buffer_usage(uint32_t rhi_usage) {
  wgpu::BufferUsage out = wgpu::BufferUsage::None;
  if (rhi_usage & rhi::buffer_usage::copy_src) out |= wgpu::BufferUsage::CopySrc;
  if (rhi_usage & rhi::buffer_usage::copy_dst) out |= wgpu::BufferUsage::CopyDst;
  if (rhi_usage & rhi::buffer_usage::uniform) out |= wgpu::BufferUsage::Uniform;
  if (rhi_usage & rhi::buffer_usage::storage) out |= wgpu::BufferUsage::Storage;
  if (rhi_usage & rhi::buffer_usage::vertex) out |= wgpu::BufferUsage::Vertex;
  if (rhi_usage & rhi::buffer_usage::index) out |= wgpu::BufferUsage::Index;
  return out;
}

wgpu::TextureUsage texture_usage(Usage usage) {
  switch (usage) {
    case Usage::sampled: return wgpu::TextureUsage::TextureBinding;
    // A shader's read-only storage image reaches Dawn as a texture binding (layout_entry):
    // the storage that reads may bind one level that way.
    case Usage::storage_read:
    case Usage::storage_read_write: return wgpu::TextureUsage::StorageBinding | wgpu::TextureUsage::TextureBinding;
    case Usage::storage_write: return wgpu::TextureUsage::StorageBinding;
    case Usage::color_attachment:
    case Usage::color_attachment_load:
    case Usage::depth_attachment:
    case Usage::depth_read: return wgpu::TextureUsage::RenderAttachment;
    case Usage::copy_src: return wgpu::TextureUsage::CopySrc;
    case Usage::copy_dst: return wgpu::TextureUsage::CopyDst;
    case Usage::uniform_read: break;
  }
  return wgpu::TextureUsage::None;
}

wgpu::BufferUsage buffer_usage(Usage usage) {
  switch (usage) {
    case Usage::uniform_read: return wgpu::BufferUsage::Uniform;
    case Usage::storage_read:
    case Usage::storage_write:
    case Usage::storage_read_write: return wgpu::BufferUsage::Storage;
    case Usage::copy_src: return wgpu::BufferUsage::CopySrc;
    case Usage::copy_dst: return wgpu::BufferUsage::CopyDst;
    default: return wgpu::BufferUsage::None;
  }
}

wgpu::VertexFormat to_wgpu(rhi::VertexFormat format) {
  switch (format) {
    case rhi::VertexFormat::float32x2: return wgpu::VertexFormat::Float32x2;
    case rhi::VertexFormat::float32x3: return wgpu::VertexFormat::Float32x3;
    case rhi::VertexFormat::float32x4: return wgpu::VertexFormat::Float32x4;
  }
  return wgpu::VertexFormat::Float32x4;
}

wgpu::CompareFunction to_wgpu(rhi::CompareFunction function) {
  using C = wgpu::CompareFunction;
  switch (function) {
    case rhi::CompareFunction::never: return C::Never;
    case rhi::CompareFunction::less: return C::Less;
    case rhi::CompareFunction::less_equal: return C::LessEqual;
    case rhi::CompareFunction::greater: return C::Greater;
    case rhi::CompareFunction::greater_equal: return C::GreaterEqual;
    case rhi::CompareFunction::equal: return C::Equal;
    case rhi::CompareFunction::not_equal: return C::NotEqual;
    case rhi::CompareFunction::always: return C::Always;
  }
  return C::Always;
}

wgpu::AddressMode to_wgpu(rhi::AddressMode mode) {
  switch (mode) {
    case rhi::AddressMode::repeat: return wgpu::AddressMode::Repeat;
    case rhi::AddressMode::mirror_repeat: return wgpu::AddressMode::MirrorRepeat;
    case rhi::AddressMode::clamp_to_edge: break;
  }
  return wgpu::AddressMode::ClampToEdge;
}

wgpu::FilterMode to_wgpu(rhi::Filter filter) {
  return filter == rhi::Filter::linear ? wgpu::FilterMode::Linear : wgpu::FilterMode::Nearest;
}

wgpu::MipmapFilterMode mipmap_filter(rhi::Filter filter) {
  return filter == rhi::Filter::linear ? wgpu::MipmapFilterMode::Linear : wgpu::MipmapFilterMode::Nearest;
}

wgpu::CullMode to_wgpu(rhi::CullMode mode) {
  switch (mode) {
    case rhi::CullMode::front: return wgpu::CullMode::Front;
    case rhi::CullMode::back: return wgpu::CullMode::Back;
    case rhi::CullMode::none: break;
  }
  return wgpu::CullMode::None;
}

wgpu::StorageTextureAccess to_wgpu(rhi::StorageAccess access) {
  switch (access) {
    case rhi::StorageAccess::read_only: return wgpu::StorageTextureAccess::ReadOnly;
    case rhi::StorageAccess::write_only: return wgpu::StorageTextureAccess::WriteOnly;
    case rhi::StorageAccess::read_write: break;
  }
  return wgpu::StorageTextureAccess::ReadWrite;
}

wgpu::ShaderStage shader_stages(uint32_t rhi_visibility) {
  wgpu::ShaderStage out = wgpu::ShaderStage::None;
  if (rhi_visibility & rhi::shader_stage::vertex) out |= wgpu::ShaderStage::Vertex;
  if (rhi_visibility & rhi::shader_stage::fragment) out |= wgpu::ShaderStage::Fragment;
  if (rhi_visibility & rhi::shader_stage::compute) out |= wgpu::ShaderStage::Compute;
  return out;
}

}  // namespace volgraph::webgpu
