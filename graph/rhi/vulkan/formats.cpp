#include "graph/rhi/vulkan/formats.h"

namespace volgraph::vulkan {

VkFormat to_vk(Format format) {
  switch (format) {
    case Format::undefined: return VK_FORMAT_UNDEFINED;
    case Format::r8_unorm: return VK_FORMAT_R8_UNORM;
    case Format::rgba8_unorm: return VK_FORMAT_R8G8B8A8_UNORM;
    case Format::rgba8_srgb: return VK_FORMAT_R8G8B8A8_SRGB;
    case Format::r16_float: return VK_FORMAT_R16_SFLOAT;
    case Format::rg16_float: return VK_FORMAT_R16G16_SFLOAT;
    case Format::rgba16_float: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case Format::r32_float: return VK_FORMAT_R32_SFLOAT;
    case Format::rg32_float: return VK_FORMAT_R32G32_SFLOAT;
    case Format::rgba32_float: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case Format::r11g11b10_float: return VK_FORMAT_B10G11R11_UFLOAT_PACK32;
    case Format::r32_uint: return VK_FORMAT_R32_UINT;
    case Format::d16_unorm: return VK_FORMAT_D16_UNORM;
    case Format::d32_float: return VK_FORMAT_D32_SFLOAT;
  }
  return VK_FORMAT_UNDEFINED;
}

VkImageUsageFlags image_usage(Usage usage) {
  switch (usage) {
    case Usage::sampled: return VK_IMAGE_USAGE_SAMPLED_BIT;
    case Usage::storage_read:
    case Usage::storage_write:
    case Usage::storage_read_write: return VK_IMAGE_USAGE_STORAGE_BIT;
    case Usage::color_attachment:
    case Usage::color_attachment_load: return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    case Usage::depth_attachment:
    case Usage::depth_read: return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    case Usage::copy_src: return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    case Usage::copy_dst: return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    case Usage::uniform_read: return 0;
  }
  return 0;
}

VkBufferUsageFlags buffer_usage(Usage usage) {
  switch (usage) {
    case Usage::uniform_read: return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    case Usage::storage_read:
    case Usage::storage_write:
    case Usage::storage_read_write: return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    case Usage::copy_src: return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    case Usage::copy_dst: return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    default: return 0;
  }
}

VkFormatFeatureFlags format_features(Usage usage) {
  switch (usage) {
    case Usage::sampled: return VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    case Usage::storage_read:
    case Usage::storage_write:
    case Usage::storage_read_write: return VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT;
    case Usage::color_attachment:
    case Usage::color_attachment_load: return VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
    case Usage::depth_attachment:
    case Usage::depth_read: return VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT;
    case Usage::copy_src: return VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    case Usage::copy_dst: return VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    case Usage::uniform_read: return 0;
  }
  return 0;
}

}  // namespace volgraph::vulkan
