// The viewer's overlay: Dear ImGui (Debian's libimgui-dev: its GLFW platform backend) with
// a renderer per window backend. Vulkan: ImGui's Vulkan backend, drawn in the present
// submission over the copied frame, in the Presenter's render pass with the backend's own
// pipeline and a descriptor pool of the viewer's. WebGPU: volgraph's own renderer on the
// CPU (cpu_overlay.cpp), over the frame's bytes before they are written to the surface —
// Debian's ImGui 1.86 ships a WebGPU renderer for an older webgpu.h than Dawn's, and the
// frame already reaches the window through the host. None of it is part of the graph
// (docs/viewer.md "Overlay"). What it shows is the loop's (viewer.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "graph/rhi/types.h"

struct GLFWwindow;

namespace volgraph::vulkan {
class Context;
}

namespace volgraph::viewer {

class Presenter;

// The ImGui context and its GLFW callbacks (installed after the window's own: it chains them).
class Overlay {
 public:
  virtual ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // A new ImGui frame: widgets may be declared until end_frame().
  void begin_frame();
  void end_frame();
  // ImGui takes the mouse or keyboard (a widget is hovered or edited): the fly camera does not.
  bool wants_mouse() const;
  bool wants_keyboard() const;

 protected:
  explicit Overlay(GLFWwindow* window, bool vulkan);
  virtual void new_renderer_frame() = 0;
};

// ImGui's Vulkan renderer in the Presenter's render pass.
class VulkanOverlay final : public Overlay {
 public:
  VulkanOverlay(vulkan::Context& context, GLFWwindow* window, Presenter& presenter);
  ~VulkanOverlay() override;
  // Records the frame's draws (inside the Presenter's render pass).
  void draw(VkCommandBuffer cmd) const;

 private:
  void new_renderer_frame() override;
  vulkan::Context& context_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

// volgraph's CPU renderer of ImGui's draw lists: triangles with their clip rectangles, the
// font atlas sampled at the nearest texel, colours interpolated, blended "over" in the
// 8-bit sRGB-encoded bytes as a UNORM swapchain blends them.
class CpuOverlay final : public Overlay {
 public:
  explicit CpuOverlay(GLFWwindow* window);
  ~CpuOverlay() override;
  // Draws the last end_frame()'s lists over `rgba8` (size's pixels, RGBA rows top first).
  void draw(std::vector<uint8_t>& rgba8, Extent size) const;

 private:
  void new_renderer_frame() override {}
  int atlas_width_ = 0, atlas_height_ = 0;
  std::vector<uint8_t> atlas_;  // the font atlas' alpha, one byte a texel
};

}  // namespace volgraph::viewer
