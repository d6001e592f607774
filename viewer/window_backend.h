// What the viewer's loop renders with and presents through: a device of one backend and
// the window's swapchain on it (Vulkan: vulkan_window.cpp; WebGPU: webgpu_window.cpp).
// The frame reaches the window by a CPU round trip on both (docs/viewer.md "Presenting").
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <memory>
#include <string>
#include <vector>

#include "graph/rhi/rhi.h"
#include "graph/rhi/types.h"

struct GLFWwindow;

namespace volgraph::viewer {

class Overlay;
struct ViewOptions;

// Swaps red and blue in place (RGBA ↔ BGRA): for swapchains that offer BGRA only.
inline void swap_red_blue(uint8_t* texels, size_t count) {
  for (size_t i = 0; i < count; ++i) std::swap(texels[i * 4], texels[i * 4 + 2]);
}

class WindowBackend {
 public:
  virtual ~WindowBackend() = default;
  // The device the graph runs on.
  virtual rhi::Device& device() = 0;
  // The swapchain's size in pixels (depth 1).
  virtual Extent extent() const = 0;
  // present() can read back what it presented (the swapchain's images are copyable from).
  virtual bool readable() const = 0;
  // A swapchain for a window of `window` pixels (resized, or stale()).
  virtual void recreate(Extent window) = 0;
  // The last present found the swapchain suboptimal or out of date.
  virtual bool stale() const = 0;
  // Copies `rgba8` (extent()'s size, RGBA rows top first, sRGB-encoded) into the next
  // swapchain image, draws `overlay`'s frame over it when given, reads the image back into
  // `presented` when given (ignored unless readable()) and presents it. False, presenting
  // nothing, when the swapchain is out of date.
  virtual bool present(const std::vector<uint8_t>& rgba8, std::vector<uint8_t>* presented, const Overlay* overlay) = 0;
  // The Dear ImGui overlay with this backend's renderer (overlay.h); present() is given it back.
  virtual std::unique_ptr<Overlay> make_overlay(GLFWwindow* window) = 0;
  // The validation layer's (Vulkan) or Dawn's (WebGPU) messages since the last call.
  virtual std::vector<std::string> take_messages() = 0;
};

// Throws DeviceError (no device, or one that cannot present to the window).
std::unique_ptr<WindowBackend> make_vulkan_window(GLFWwindow* window, const ViewOptions& options);
// Throws DeviceError as above, and unsupported where volgraph was built without Dawn or
// the window is not an X11 one.
std::unique_ptr<WindowBackend> make_webgpu_window(GLFWwindow* window, const ViewOptions& options);

}  // namespace volgraph::viewer
