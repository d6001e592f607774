// The Vulkan 1.3 instance, device and queue volgraph renders with: Mesa lavapipe by
// default (any Vulkan 1.3 driver by index), synchronization2 and dynamic rendering on,
// and, when asked, the Khronos validation layer with synchronization validation whose
// messages are collected so that tests can fail on any of them.
// Only the Vulkan backend and its tests include this header (it pulls in vulkan.h).
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "graph/rhi/device_error.h"

namespace volgraph::vulkan {

// A driver failure to act out, so that the way volgraph reports it can be tested on a
// driver that never fails: every memory allocation returns
// VK_ERROR_OUT_OF_DEVICE_MEMORY, or every queue submission VK_ERROR_DEVICE_LOST.
using SimulatedFault = volgraph::SimulatedFault;

struct ContextOptions {
  bool validation = false;       // VK_LAYER_KHRONOS_validation, synchronization validation included
  int device_index = -1;         // -1: lavapipe when present, else the first Vulkan 1.3 device
  SimulatedFault simulate = SimulatedFault::none;
  // Beyond volgraph's own: what a window needs (viewer/: the surface's instance
  // extensions from GLFW, VK_KHR_swapchain on the device).
  std::vector<const char*> instance_extensions;
  std::vector<const char*> device_extensions;
};

struct DeviceInfo {
  std::string name;
  std::string driver;
  uint32_t api_version = 0;
  uint32_t vendor_id = 0;
  bool dual_source_blending = false;  // VkPhysicalDeviceFeatures::dualSrcBlend
};

class Context {
 public:
  // Throws DeviceError (no_device, unsupported, …) with a message a user can act on.
  static std::unique_ptr<Context> create(const ContextOptions& options);
  static std::vector<DeviceInfo> list_devices();
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  const DeviceInfo& info() const { return info_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }
  float timestamp_period_ns() const { return limits_.timestampPeriod; }
  bool validation() const { return messenger_ != VK_NULL_HANDLE; }

  // Labels an object for validation messages and frame debuggers (VK_EXT_debug_utils).
  void set_name(VkObjectType type, uint64_t handle, const std::string& name) const;

  // Command-buffer labels (VK_EXT_debug_utils), when the loader has the extension.
  bool has_debug_labels() const { return begin_label_ != nullptr; }
  void begin_label(VkCommandBuffer cmd, const VkDebugUtilsLabelEXT& label) const { begin_label_(cmd, &label); }
  void end_label(VkCommandBuffer cmd) const { end_label_(cmd); }

  // Validation messages (warnings and errors) since the last take.
  std::vector<std::string> take_validation_messages();

  // Records with `record`, submits, waits. For set-up, uploads and readbacks.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record);
  // Submits a recorded command buffer and waits for it; the result for check().
  VkResult submit_recorded(VkCommandBuffer cmd);
  // One block of device memory. Throws DeviceError out_of_memory when the driver
  // refuses, or before asking when `size` exceeds what one allocation may hold
  // (maxMemoryAllocationSize) or the heap.
  VkDeviceMemory allocate_memory(uint64_t size, uint32_t memory_type, const std::string& label);
  // A memory type index with `required` properties among `type_bits`; throws when none.
  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags required) const;

 private:
  Context() = default;
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
  void create_instance(bool validation, const std::vector<const char*>& extra_extensions);
  void pick_device(int index);
  void create_device(const std::vector<const char*>& extra_extensions);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  PFN_vkSetDebugUtilsObjectNameEXT set_name_ = nullptr;
  PFN_vkCmdBeginDebugUtilsLabelEXT begin_label_ = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT end_label_ = nullptr;
  DeviceInfo info_;
  VkPhysicalDeviceLimits limits_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  uint64_t max_allocation_size_ = 0;
  SimulatedFault simulate_ = SimulatedFault::none;
  std::mutex messages_mutex_;
  std::vector<std::string> messages_;
};

// Throws the DeviceError a failed call deserves (out of memory, device lost, …).
void check(VkResult result, const char* what);

}  // namespace volgraph::vulkan
