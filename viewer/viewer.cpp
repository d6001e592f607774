#include "viewer/viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <vector>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "graph/execute/executor.h"
#include "graph/rhi/vulkan/context.h"
#include "graph/rhi/vulkan/vulkan_device.h"
#include "physics/srgb.h"
#include "tools/image_io.h"
#include "tools/output_files.h"
#include "viewer/presenter.h"

namespace volgraph::viewer {
namespace {

// Frames rendered after a change before the loop idles: temporal passes (history
// pairs) converge over frames, so a static scene keeps rendering this long.
constexpr int kSettleFrames = 32;
// How long an idle loop sleeps in glfwWaitEventsTimeout between checks (seconds).
constexpr double kIdleWait = 0.25;

// What the callbacks tell the loop (the window's user pointer).
struct WindowEvents {
  bool resized = false;
  bool exposed = false;
};

// GLFW initialised for the loop's lifetime; its failure is the user's setup (no display).
struct GlfwSession {
  GlfwSession() {
    if (!glfwInit()) {
      const char* why = nullptr;
      glfwGetError(&why);
      throw NoDisplay(std::string("view: cannot open a window: ") + (why ? why : "GLFW could not start") +
                      "; run it on a desktop or under xvfb-run -a");
    }
  }
  ~GlfwSession() { glfwTerminate(); }
  GlfwSession(const GlfwSession&) = delete;
  GlfwSession& operator=(const GlfwSession&) = delete;
};

struct WindowDeleter {
  void operator()(GLFWwindow* w) const { glfwDestroyWindow(w); }
};
using Window = std::unique_ptr<GLFWwindow, WindowDeleter>;

Window open_window(Extent size, const std::string& title, WindowEvents& events) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan draws, not OpenGL
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  Window window(glfwCreateWindow(int(size.width), int(size.height), title.c_str(), nullptr, nullptr));
  if (!window) throw NoDisplay("view: the display refused a " + std::to_string(size.width) + "x" + std::to_string(size.height) + " window");
  glfwSetWindowUserPointer(window.get(), &events);
  glfwSetFramebufferSizeCallback(window.get(), [](GLFWwindow* w, int, int) {
    static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->resized = true;
  });
  glfwSetWindowRefreshCallback(window.get(), [](GLFWwindow* w) { static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->exposed = true; });
  // ESC closes the window (docs/viewer.md "Keys").
  glfwSetKeyCallback(window.get(), [](GLFWwindow* w, int key, int, int action, int) {
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
  });
  return window;
}

VkExtent2D framebuffer_extent(GLFWwindow* window) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window, &w, &h);
  return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

// The frame's output as `render` writes it to a PNG (tools/image_io.cpp encode_png):
// colour sRGB-encoded, alpha clamped, each rounded to 8 bits.
std::vector<uint8_t> srgb8(const Texels& t) {
  std::vector<uint8_t> out(t.rgba.size());
  for (size_t i = 0; i < t.rgba.size(); ++i) {
    const float v = (i % 4 == 3) ? std::clamp(t.rgba[i], 0.0f, 1.0f) : physics::srgb_encode(t.rgba[i]);
    out[i] = uint8_t(std::lround(v * 255.0f));
  }
  return out;
}

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

void write_screenshot(const std::string& path, VkExtent2D extent, const std::vector<uint8_t>& rgba8) {
  OutputFiles files;
  files.stage(path, "--screenshot", encode_png_rgba8(extent.width, extent.height, rgba8));
  files.commit();
}

// The loop: one frame of the graph, its output copied into the swapchain and presented;
// a resize recompiles the graph at the new size (resize(), no config reload); idle
// (glfwWaitEventsTimeout) once a static scene has settled.
class Loop {
 public:
  Loop(vulkan::Context& context, GLFWwindow* window, LoadedConfig& loaded, const ViewOptions& options)
      : context_(context), window_(window), loaded_(loaded), options_(options), device_(context),
        presenter_(context, create_surface(context, window), framebuffer_extent(window)) {
    restart();
  }

  void run(WindowEvents& events) {
    while (!glfwWindowShouldClose(window_)) {
      if (events.resized || presenter_.stale()) {
        events.resized = false;
        if (!resize_to_window()) continue;
      }
      if (events.exposed) settled_ = std::min(settled_, kSettleFrames - 1);  // present again
      events.exposed = false;
      if (options_.frames == 0 && settled_ >= kSettleFrames) {
        glfwWaitEventsTimeout(kIdleWait);
        continue;
      }
      const bool last = options_.frames > 0 && rendered_ + 1 == options_.frames;
      // Until the window closes, any frame may be the last: each is read back for --screenshot.
      const bool keep = !options_.screenshot.empty() && (last || options_.frames == 0);
      if (!frame(keep)) {
        events.resized = true;
        continue;
      }
      if (last) break;
      glfwPollEvents();
    }
    if (!options_.screenshot.empty() && !shot_.empty()) write_screenshot(options_.screenshot, shot_extent_, shot_);
  }

 private:
  // The executor for the swapchain's size: the graph resized when it differs.
  void restart() {
    executor_.reset();
    const VkExtent2D e = presenter_.extent();
    const Extent size{e.width, e.height, 1};
    if (size.width != loaded_.config.output_size.width || size.height != loaded_.config.output_size.height) {
      loaded_.config.output_size = size;
      resize(loaded_.graph, size);
    }
    executor_ = std::make_unique<Executor>(device_, loaded_.graph, &loaded_.config.scene, options_.compile);
    executor_->set_gpu_timing(false);  // nothing shows pass times yet (no overlay): frames without time stamps
    settled_ = 0;
  }

  // False while the window is minimised (nothing to present to).
  bool resize_to_window() {
    const VkExtent2D window = framebuffer_extent(window_);
    if (window.width == 0 || window.height == 0) {
      glfwWaitEvents();
      return false;
    }
    presenter_.recreate(window);
    restart();
    return true;
  }

  bool frame(bool screenshot) {
    executor_->run_frame();
    const std::vector<uint8_t> texels = srgb8(executor_->read_output(0));
    std::vector<uint8_t>* read_back = screenshot && presenter_.readable() ? &shot_ : nullptr;
    if (!presenter_.present(texels, read_back)) return false;
    if (screenshot) shot_extent_ = presenter_.extent();
    if (screenshot && !read_back) shot_ = texels;  // swapchain images not copyable from: the bytes presented
    ++rendered_;
    ++settled_;
    return true;
  }

  vulkan::Context& context_;
  GLFWwindow* window_;
  LoadedConfig& loaded_;
  const ViewOptions& options_;
  vulkan::VulkanDevice device_;
  Presenter presenter_;
  std::unique_ptr<Executor> executor_;
  int rendered_ = 0;
  int settled_ = 0;
  std::vector<uint8_t> shot_;  // the last presented image, for --screenshot
  VkExtent2D shot_extent_{};
};

}  // namespace

int run(LoadedConfig& loaded, const ViewOptions& options) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) {
    throw NoDisplay("view: no display to open a window on (DISPLAY is not set); run it on a desktop or under xvfb-run -a");
  }
  GlfwSession glfw;
  WindowEvents events;
  Window window = open_window(loaded.config.output_size, options.title, events);
  std::unique_ptr<vulkan::Context> context = create_context(options);
  {
    Loop loop(*context, window.get(), loaded, options);
    loop.run(events);
  }
  const std::vector<std::string> messages = context->take_validation_messages();
  for (const std::string& m : messages) std::cerr << "validation: " << m << "\n";
  return messages.empty() ? 0 : 1;
}

}  // namespace volgraph::viewer
