#include "viewer/presenter.h"

#include "viewer/window_backend.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace volgraph::viewer {
namespace {

using vulkan::check;

// The swapchain's format: 8-bit UNORM (the bytes written are sRGB-encoded already, as
// in a PNG), BGRA or RGBA, whichever the surface offers.
VkSurfaceFormatKHR pick_format(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t n = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(n);
  vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, formats.data());
  for (const VkSurfaceFormatKHR& f : formats) {
    if ((f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) &&
        f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
      return f;
    }
  }
  throw DeviceError(DeviceError::Kind::unsupported, "the window surface offers no 8-bit UNORM BGRA or RGBA format");
}

bool bgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_UNORM; }

VkImageMemoryBarrier2 image_barrier(VkImage image, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access, VkImageLayout from,
                                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access, VkImageLayout to) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = src_stage;
  b.srcAccessMask = src_access;
  b.dstStageMask = dst_stage;
  b.dstAccessMask = dst_access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  return b;
}

void barrier(VkCommandBuffer cmd, const VkImageMemoryBarrier2& b) {
  VkDependencyInfo d{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  d.imageMemoryBarrierCount = 1;
  d.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &d);
}

}  // namespace

Presenter::Presenter(vulkan::Context& context, VkSurfaceKHR surface, VkExtent2D window) : context_(context), surface_(surface) {
  VkBool32 supported = VK_FALSE;
  vkGetPhysicalDeviceSurfaceSupportKHR(context.physical_device(), context.queue_family(), surface, &supported);
  if (!supported) {
    vkDestroySurfaceKHR(context.instance(), surface, nullptr);
    throw DeviceError(DeviceError::Kind::unsupported, context.info().name + " cannot present to this window");
  }
  format_ = pick_format(context.physical_device(), surface);
  create_render_pass();
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = context.queue_family();
  check(vkCreateCommandPool(context.device(), &pool, nullptr, &pool_), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  check(vkAllocateCommandBuffers(context.device(), &alloc, &cmd_), "vkAllocateCommandBuffers");
  VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  check(vkCreateSemaphore(context.device(), &semaphore, nullptr, &acquired_), "vkCreateSemaphore");
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  check(vkCreateFence(context.device(), &fence, nullptr, &done_), "vkCreateFence");
  create_swapchain(window);
}

Presenter::~Presenter() {
  vkDeviceWaitIdle(context_.device());
  destroy_swapchain();
  vkDestroyFence(context_.device(), done_, nullptr);
  vkDestroySemaphore(context_.device(), acquired_, nullptr);
  vkDestroyCommandPool(context_.device(), pool_, nullptr);
  vkDestroyRenderPass(context_.device(), render_pass_, nullptr);
  vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
}

// The overlay's render pass: the image arrives from the copy (TRANSFER_DST, its write
// made visible to the attachment's load by the dependency) and is kept (LOAD); it leaves
// as COLOR_ATTACHMENT_OPTIMAL, and record_copy's barriers take it on from there.
void Presenter::create_render_pass() {
  VkAttachmentDescription color{};
  color.format = format_.format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkSubpassDependency after_copy{};
  after_copy.srcSubpass = VK_SUBPASS_EXTERNAL;
  after_copy.dstSubpass = 0;
  after_copy.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  after_copy.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  after_copy.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after_copy.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after_copy;
  check(vkCreateRenderPass(context_.device(), &info, nullptr, &render_pass_), "vkCreateRenderPass");
}

void Presenter::submit_now(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
  record(cmd_);
  check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
  VkCommandBufferSubmitInfo command{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  command.commandBuffer = cmd_;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &command;
  check(vkQueueSubmit2(context_.queue(), 1, &submit, done_), "vkQueueSubmit2");
  check(vkWaitForFences(context_.device(), 1, &done_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  check(vkResetFences(context_.device(), 1, &done_), "vkResetFences");
}

void Presenter::recreate(VkExtent2D window) {
  vkDeviceWaitIdle(context_.device());
  destroy_swapchain();
  create_swapchain(window);
  stale_ = false;
}

void Presenter::create_swapchain(VkExtent2D window) {
  VkSurfaceCapabilitiesKHR caps{};
  check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical_device(), surface_, &caps), "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  extent_ = caps.currentExtent;
  if (extent_.width == UINT32_MAX) {  // the surface takes the swapchain's size: the window's
    extent_.width = std::clamp(window.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(window.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT)) {
    throw DeviceError(DeviceError::Kind::unsupported, "the window's swapchain images cannot be copied into (no TRANSFER_DST usage)");
  }
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = caps.maxImageCount ? std::min(caps.minImageCount + 1, caps.maxImageCount) : caps.minImageCount + 1;
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  // TRANSFER_SRC where offered: --screenshot reads the presented image back.
  // COLOR_ATTACHMENT (always offered): the overlay draws into the image after the copy.
  info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                    (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  for (VkCompositeAlphaFlagBitsKHR a : {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
                                        VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR}) {
    if (caps.supportedCompositeAlpha & a) {
      info.compositeAlpha = a;
      break;
    }
  }
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always offered; paces presents to the display
  info.clipped = VK_TRUE;
  check(vkCreateSwapchainKHR(context_.device(), &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
  uint32_t n = 0;
  vkGetSwapchainImagesKHR(context_.device(), swapchain_, &n, nullptr);
  images_.resize(n);
  vkGetSwapchainImagesKHR(context_.device(), swapchain_, &n, images_.data());
  for (VkImage image : images_) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_.format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    check(vkCreateImageView(context_.device(), &view, nullptr, &views_.emplace_back()), "vkCreateImageView");
    VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fb.renderPass = render_pass_;
    fb.attachmentCount = 1;
    fb.pAttachments = &views_.back();
    fb.width = extent_.width;
    fb.height = extent_.height;
    fb.layers = 1;
    check(vkCreateFramebuffer(context_.device(), &fb, nullptr, &framebuffers_.emplace_back()), "vkCreateFramebuffer");
  }
  VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  rendered_.resize(n);
  for (VkSemaphore& s : rendered_) check(vkCreateSemaphore(context_.device(), &semaphore, nullptr, &s), "vkCreateSemaphore");
  const VkDeviceSize bytes = VkDeviceSize(extent_.width) * extent_.height * 4;
  upload_ = make_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "viewer upload");
  if (info.imageUsage & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) readback_ = make_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "viewer screenshot");
}

void Presenter::destroy_swapchain() {
  destroy_buffer(upload_);
  destroy_buffer(readback_);
  for (VkSemaphore s : rendered_) vkDestroySemaphore(context_.device(), s, nullptr);
  rendered_.clear();
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(context_.device(), f, nullptr);
  for (VkImageView v : views_) vkDestroyImageView(context_.device(), v, nullptr);
  framebuffers_.clear();
  views_.clear();
  images_.clear();
  vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
}

Presenter::HostBuffer Presenter::make_buffer(VkDeviceSize size, VkBufferUsageFlags usage, const char* label) {
  HostBuffer b;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  check(vkCreateBuffer(context_.device(), &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(context_.device(), b.buffer, &req);
  const uint32_t type = context_.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  b.memory = context_.allocate_memory(req.size, type, label);
  check(vkBindBufferMemory(context_.device(), b.buffer, b.memory, 0), "vkBindBufferMemory");
  check(vkMapMemory(context_.device(), b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  return b;
}

void Presenter::destroy_buffer(HostBuffer& b) {
  if (b.buffer) vkDestroyBuffer(context_.device(), b.buffer, nullptr);
  if (b.memory) vkFreeMemory(context_.device(), b.memory, nullptr);
  b = {};
}

// The present copy's barriers: the acquired image (contents undefined, the acquire
// semaphore waited at the copy stage) to TRANSFER_DST; the buffer copied in; for a
// screenshot TRANSFER_DST → TRANSFER_SRC and the image copied out; then to PRESENT_SRC
// (no later access in this queue: the present waits on the `rendered_` semaphore).
void Presenter::record_copy(uint32_t index, bool read_back, const std::function<void(VkCommandBuffer)>& overlay) {
  const VkImage image = images_[index];
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer");
  barrier(cmd_, image_barrier(image, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED,
                              VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL));
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyBufferToImage(cmd_, upload_.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  VkAccessFlags2 written = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COPY_BIT;
  if (overlay) {  // drawn over the copied frame (the render pass's dependency orders it after the copy)
    VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    pass.renderPass = render_pass_;
    pass.framebuffer = framebuffers_[index];
    pass.renderArea = {{0, 0}, extent_};
    vkCmdBeginRenderPass(cmd_, &pass, VK_SUBPASS_CONTENTS_INLINE);
    overlay(cmd_);
    vkCmdEndRenderPass(cmd_);
    layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    written = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
    stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  }
  if (read_back) {
    barrier(cmd_, image_barrier(image, stage, written, layout,
                                VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL));
    layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    written = VK_ACCESS_2_NONE;  // a read: an execution dependency is enough
    stage = VK_PIPELINE_STAGE_2_COPY_BIT;
    vkCmdCopyImageToBuffer(cmd_, image, layout, readback_.buffer, 1, &region);
    VkMemoryBarrier2 host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};  // the copy's writes, visible to the host after the fence
    host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo d{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    d.memoryBarrierCount = 1;
    d.pMemoryBarriers = &host;
    vkCmdPipelineBarrier2(cmd_, &d);
  }
  barrier(cmd_, image_barrier(image, stage, written, layout, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                              VK_IMAGE_LAYOUT_PRESENT_SRC_KHR));
  check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
}

bool Presenter::present(const std::vector<uint8_t>& rgba8, std::vector<uint8_t>* presented,
                        const std::function<void(VkCommandBuffer)>& overlay) {
  const size_t texels = size_t(extent_.width) * extent_.height;
  if (rgba8.size() != texels * 4) throw std::invalid_argument("Presenter::present: the texels do not match the swapchain's size");
  if (!readable()) presented = nullptr;
  uint32_t index = 0;
  const VkResult acquired = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) return false;
  if (acquired != VK_SUBOPTIMAL_KHR) check(acquired, "vkAcquireNextImageKHR");
  std::memcpy(upload_.mapped, rgba8.data(), rgba8.size());
  if (bgra(format_.format)) swap_red_blue(static_cast<uint8_t*>(upload_.mapped), texels);
  record_copy(index, presented != nullptr, overlay);

  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = acquired_;
  // The copy into the image (and the overlay after it) waits for the acquire.
  wait.stageMask = VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = rendered_[index];
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo command{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  command.commandBuffer = cmd_;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &command;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  check(vkQueueSubmit2(context_.queue(), 1, &submit, done_), "vkQueueSubmit2");

  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &rendered_[index];
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index;
  const VkResult shown = vkQueuePresentKHR(context_.queue(), &info);
  // One frame in flight: the upload buffer, command buffer and acquire semaphore are reused next frame.
  check(vkWaitForFences(context_.device(), 1, &done_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  check(vkResetFences(context_.device(), 1, &done_), "vkResetFences");
  if (shown != VK_SUBOPTIMAL_KHR && shown != VK_ERROR_OUT_OF_DATE_KHR) check(shown, "vkQueuePresentKHR");
  if (presented) {
    presented->assign(static_cast<const uint8_t*>(readback_.mapped), static_cast<const uint8_t*>(readback_.mapped) + texels * 4);
    if (bgra(format_.format)) swap_red_blue(presented->data(), texels);
  }
  stale_ = shown != VK_SUCCESS;
  return true;
}

}  // namespace volgraph::viewer
