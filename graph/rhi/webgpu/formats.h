// volgraph's formats, usages and fixed-function states in WebGPU terms (the Dawn-style
// C++ API of <webgpu/webgpu_cpp.h>).
#pragma once

#include <webgpu/webgpu_cpp.h>

#include "graph/access.h"
#include "graph/resource.h"
#include "graph/rhi/rhi.h"

namespace volgraph::webgpu {

wgpu::TextureFormat to_wgpu(Format format);
wgpu::TextureDimension dimension_of(ResourceKind kind);
// A cube's view is the cube; `cube_faces`: its faces as a 2D array (storage writes).
wgpu::TextureViewDimension view_dimension_of(ResourceKind kind, bool cube_faces = false);
// The aspect a copy of the whole texture names: depth formats copy their depth only.
wgpu::TextureAspect copy_aspect(Format format);

// rhi usage bits (rhi::texture_usage, rhi::buffer_usage) as WebGPU's.
wgpu::TextureUsage texture_usage(uint32_t rhi_usage);
wgpu::BufferUsage buffer_usage(uint32_t rhi_usage);
// What one use of a graph resource needs (none for usages of the other kind).
wgpu::TextureUsage texture_usage(Usage usage);
wgpu::BufferUsage buffer_usage(Usage usage);

wgpu::VertexFormat to_wgpu(rhi::VertexFormat format);
wgpu::CompareFunction to_wgpu(rhi::CompareFunction function);
wgpu::AddressMode to_wgpu(rhi::AddressMode mode);
wgpu::FilterMode to_wgpu(rhi::Filter filter);
wgpu::MipmapFilterMode mipmap_filter(rhi::Filter filter);
wgpu::CullMode to_wgpu(rhi::CullMode mode);
wgpu::StorageTextureAccess to_wgpu(rhi::StorageAccess access);
wgpu::ShaderStage shader_stages(uint32_t rhi_visibility);

}  // namespace volgraph::webgpu
