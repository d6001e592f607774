// The viewer on Vulkan: a context with the window-surface extensions GLFW asks for, the
// graph's device on it, and the Presenter's swapchain (presenter.h) with the Dear ImGui
// overlay drawn in its render pass.
#include <algorithm>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "graph/rhi/vulkan/context.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "viewer/overlay.h"
#include "viewer/presenter.h"
#include "viewer/viewer.h"
#include "viewer/window_backend.h"

namespace volgraph::viewer {
namespace {

std::unique_ptr<vulkan::Context> create_context(const ViewOptions& options) {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw DeviceError(DeviceError::Kind::unsupported, "GLFW found no Vulkan window-surface support (glfwGetRequiredInstanceExtensions)");
  vulkan::ContextOptions context;
  context.validation = options.validation;
  context.device_index = options.device;
  context.instance_extensions.assign(names, names + count);
  context.device_extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  return vulkan::Context::create(context);
}

VkSurfaceKHR create_surface(vulkan::Context& context, GLFWwindow* window) {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  vulkan::check(glfwCreateWindowSurface(context.instance(), window, nullptr, &surface), "glfwCreateWindowSurface");
  return surface;
}

VkExtent2D framebuffer_size(GLFWwindow* window) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window, &w, &h);
  return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

class VulkanWindow final : public WindowBackend {
 public:
  VulkanWindow(GLFWwindow* window, const ViewOptions& options)
      : context_(create_context(options)), device_(*context_),
        presenter_(*context_, create_surface(*context_, window), framebuffer_size(window)) {}

  rhi::Device& device() override { return device_; }
  Extent extent() const override { return {presenter_.extent().width, presenter_.extent().height, 1}; }
  bool readable() const override { return presenter_.readable(); }
  void recreate(Extent window) override { presenter_.recreate({window.width, window.height}); }
  bool stale() const override { return presenter_.stale(); }
  bool present(const std::vector<uint8_t>& rgba8, std::vector<uint8_t>* presented, const Overlay* overlay) override {
    std::function<void(VkCommandBuffer)> draw;
    // The loop hands back the overlay make_overlay made: a VulkanOverlay.
    if (overlay) draw = [drawn = static_cast<const VulkanOverlay*>(overlay)](VkCommandBuffer cmd) { drawn->draw(cmd); };
    return presenter_.present(rgba8, presented, draw);
  }
  std::unique_ptr<Overlay> make_overlay(GLFWwindow* window) override { return std::make_unique<VulkanOverlay>(*context_, window, presenter_); }
  std::vector<std::string> take_messages() override { return context_->take_validation_messages(); }

 private:
  std::unique_ptr<vulkan::Context> context_;
  vulkan::VulkanDevice device_;
  Presenter presenter_;
};

}  // namespace

std::unique_ptr<WindowBackend> make_vulkan_window(GLFWwindow* window, const ViewOptions& options) {
  return std::make_unique<VulkanWindow>(window, options);
}

}  // namespace volgraph::viewer
