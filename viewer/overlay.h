// The viewer's overlay: Dear ImGui (its GLFW and Vulkan backends, Debian's libimgui-dev)
// drawn in the present submission over the copied frame, in the Presenter's render pass
// with the backend's own pipeline and a descriptor pool of the viewer's: none of it is
// part of the graph (docs/viewer.md "Overlay"). What it shows is the loop's (viewer.cpp).
#pragma once

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace volgraph::vulkan {
class Context;
}

namespace volgraph::viewer {

class Presenter;

class Overlay {
 public:
  // Installs ImGui's GLFW callbacks after the window's own (it chains them).
  Overlay(vulkan::Context& context, GLFWwindow* window, Presenter& presenter);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  // A new ImGui frame: widgets may be declared until end_frame().
  void begin_frame();
  void end_frame();
  // Records the frame's draws (inside the Presenter's render pass).
  void draw(VkCommandBuffer cmd) const;
  // ImGui takes the mouse or keyboard (a widget is hovered or edited): the fly camera does not.
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  vulkan::Context& context_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

}  // namespace volgraph::viewer
