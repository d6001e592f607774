// The window's swapchain and the present copy (docs/viewer.md "Presenting").
//
// The graph cannot import a swapchain image yet, so the copy runs after the graph's
// submission: the frame's output is read back (Executor::read_output, tone-mapped by the
// composite), encoded to sRGB 8-bit exactly as `render` writes a PNG, and copied from a
// host-visible buffer into the acquired image in a submission of its own, whose barriers
// are written out in presenter.cpp (record_copy).
#pragma once

#include <cstdint>
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
  bool present(const std::vector<uint8_t>& rgba8, std::vector<uint8_t>* presented);
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
  void record_copy(VkImage image, bool read_back);

  vulkan::Context& context_;
  VkSurfaceKHR surface_;
  VkSurfaceFormatKHR format_{};
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<VkSemaphore> rendered_;  // per swapchain image: the copy done, present may start
  VkSemaphore acquired_ = VK_NULL_HANDLE;
  VkFence done_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  HostBuffer upload_, readback_;
  bool stale_ = false;
};

}  // namespace volgraph::viewer
