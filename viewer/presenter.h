// The window's swapchain and the present copy (docs/viewer.md "Presenting").
//
// The graph cannot import a swapchain image yet, so the copy runs after the graph's
// submission: the frame's output is read back (Executor::read_output, tone-mapped by the
// composite), encoded to sRGB 8-bit exactly as `render` writes a PNG, and copied from a
// host-visible buffer into the acquired image in a submission of its own, whose barriers
// are written out in presenter.cpp (record_copy).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <vulkan/vulkan.h>

#include "graph/rhi/vulkan/context.h"

namespace volgraph::viewer {

class Presenter {
 public:
  // Takes ownership of `surface` (made on context's instance). Throws DeviceError
  // (unsupported) when the context's queue cannot present to it.
  Presenter(vulkan::Context& context, VkSurfaceKHR surface, VkExtent2D window);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  VkExtent2D extent() const { return extent_; }
  // The swapchain's images can be copied from (TRANSFER_SRC): present() can read one back.
  bool readable() const { return readback_.buffer != VK_NULL_HANDLE; }
  // A new swapchain for a window of `window` pixels (resized or out of date).
  void recreate(VkExtent2D window);
  // Copies `rgba8` (extent()'s size, RGBA rows top first) into the next swapchain image and
  // presents it; when `presented` is given, the image as presented is also read back into
  // it (RGBA8; ignored unless readable()). Returns false,
  // presenting nothing, when the swapchain is out of date.
  // `overlay`, when given, records draws into the viewer's render pass (render_pass()) on
  // the image after the copy, before the read-back: a screenshot holds what it drew.
  bool present(const std::vector<uint8_t>& rgba8, std::vector<uint8_t>* presented,
               const std::function<void(VkCommandBuffer)>& overlay = {});
  // The viewer's render pass over a swapchain image (LOAD: drawn over the copied frame),
  // the overlay's; not part of the graph, as the present copy is not.
  VkRenderPass render_pass() const { return render_pass_; }
  uint32_t image_count() const { return uint32_t(images_.size()); }
  // Records `record` in a one-time submission and waits for it (the overlay's font upload).
  void submit_now(const std::function<void(VkCommandBuffer)>& record);
  // The last present found the swapchain suboptimal or out of date: recreate it.
  bool stale() const { return stale_; }

 private:
  struct HostBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
  };
  void create_swapchain(VkExtent2D window);
  void destroy_swapchain();
  HostBuffer make_buffer(VkDeviceSize size, VkBufferUsageFlags usage, const char* label);
  void destroy_buffer(HostBuffer& b);
  void record_copy(uint32_t index, bool read_back, const std::function<void(VkCommandBuffer)>& overlay);
  void create_render_pass();

  vulkan::Context& context_;
  VkSurfaceKHR surface_;
  VkSurfaceFormatKHR format_{};
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;           // per swapchain image, for framebuffers_
  std::vector<VkFramebuffer> framebuffers_;  // render_pass_ on each swapchain image
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  std::vector<VkSemaphore> rendered_;  // per swapchain image: the copy done, present may start
  VkSemaphore acquired_ = VK_NULL_HANDLE;
  VkFence done_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  HostBuffer upload_, readback_;
  bool stale_ = false;
};

}  // namespace volgraph::viewer
