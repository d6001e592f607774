// volgraph's formats and usages in Vulkan terms.
#pragma once

#include <vulkan/vulkan.h>

#include "graph/access.h"
#include "graph/resource.h"

namespace volgraph::vulkan {

VkFormat to_vk(Format format);
VkImageUsageFlags image_usage(Usage usage);
VkBufferUsageFlags buffer_usage(Usage usage);
// The format features a usage needs, to check the device supports it.
VkFormatFeatureFlags format_features(Usage usage);

}  // namespace volgraph::vulkan
