#include "viewer/viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <chrono>
#include <memory>
#include <thread>
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
// How long a script's wait-change waits for the config or an include to change (seconds).
constexpr double kWaitChange = 30.0;

// What the callbacks tell the loop (the window's user pointer).
struct WindowEvents {
  bool resized = false;
  bool exposed = false;
  bool reload = false;  // R
  bool ab = false;      // Tab: the last `ab` pair toggled again
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
    if (action != GLFW_PRESS) return;
    WindowEvents& events = *static_cast<WindowEvents*>(glfwGetWindowUserPointer(w));
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
    if (key == GLFW_KEY_R) events.reload = true;
    if (key == GLFW_KEY_TAB) events.ab = true;
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
  Loop(vulkan::Context& context, GLFWwindow* window, LoadedConfig loaded, const ViewOptions& options, WindowEvents& events)
      : context_(context), window_(window),
        source_(options.config, *options.registry, options.overrides, options.compile, std::move(loaded)),
        options_(options), events_(events), device_(context),
        presenter_(context, create_surface(context, window), framebuffer_extent(window)) {
    restart();
  }

  // The control API (docs/viewer.md "Control"): keys and --script call these. A change
  // recompiles the graph (a new executor) on the same window, swapchain and device; a
  // refused one keeps the last good graph running and shows the loader's message.
  std::string set_variant(const std::string& pass, const std::string& variant) { return applied(source_.set_variant(pass, variant)); }
  std::string set_param(const std::string& pass, const std::string& name, const std::string& json) {
    return applied(source_.set_param(pass, name, json));
  }
  std::string reload() { return applied(source_.reload()); }
  std::string toggle_ab(const std::string& pass, const std::string& a, const std::string& b) {
    ab_ = {pass, a, b};
    return applied(source_.toggle_ab(pass, a, b));
  }
  // The last presented image (one frame first when none was presented yet).
  void screenshot(const std::string& path) {
    if (shot_.empty()) frames(1);
    write_screenshot(path, shot_extent_, shot_);
  }

  // Returns the exit code's part: false when a script's wait-change timed out.
  bool run() {
    if (options_.scripted) return run_script();
    run_interactive();
    return true;
  }

 private:
  void run_interactive() {
    WindowEvents& events = events_;
    while (!glfwWindowShouldClose(window_)) {
      handle_keys();
      poll_files();
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

  bool run_script() {
    for (const ScriptCommand& c : options_.script) {
      if (glfwWindowShouldClose(window_)) break;
      if (!run_command(c)) return false;
    }
    if (!options_.screenshot.empty()) screenshot(options_.screenshot);
    return true;
  }

  bool run_command(const ScriptCommand& c) {
    const std::vector<std::string>& a = c.args;
    if (c.verb == "frames") frames(std::stoi(a[0]));
    if (c.verb == "variant") set_variant(a[0], a[1]);
    if (c.verb == "param") set_param(a[0], a[1], a[2]);
    if (c.verb == "ab") toggle_ab(a[0], a[1], a[2]);
    if (c.verb == "reload") reload();
    if (c.verb == "screenshot") screenshot(a[0]);
    if (c.verb == "wait-change" && !wait_change()) {
      std::cerr << "view: --script line " << c.line << ": wait-change: the config and its includes did not change in "
                << int(kWaitChange) << " s\n";
      return false;
    }
    return true;
  }

  // Renders `n` frames, each kept for a screenshot; keys, resizes and file changes between them.
  void frames(int n) {
    for (int done = 0; done < n && !glfwWindowShouldClose(window_);) {
      glfwPollEvents();
      handle_keys();
      poll_files();
      if ((events_.resized || presenter_.stale()) && !resize_to_window()) continue;
      events_.resized = false;
      if (frame(true)) {
        ++done;
      } else {
        events_.resized = true;
      }
    }
  }

  // Until the hot reload saw a change on disk since the last wait (or kWaitChange seconds).
  bool wait_change() {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(kWaitChange);
    while (disk_changes_ == waited_changes_ && std::chrono::steady_clock::now() < end) {
      glfwPollEvents();
      poll_files();
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const bool seen = disk_changes_ != waited_changes_;
    waited_changes_ = disk_changes_;
    return seen;
  }

  void handle_keys() {
    if (events_.reload) reload();
    if (events_.ab && !ab_.pass.empty()) toggle_ab(ab_.pass, ab_.a, ab_.b);
    events_.reload = events_.ab = false;
  }

  // Hot reload: the config or an include changed on disk.
  void poll_files() {
    if (!source_.files_changed()) return;
    ++disk_changes_;
    reload();
  }

  // After a change: the new graph runs, or the refusal is shown (title) and printed once.
  std::string applied(const std::string& error) {
    if (error.empty()) {
      restart();
      glfwSetWindowTitle(window_, options_.title.c_str());
    } else {
      std::cerr << error << "\n";
      const std::string first_line = error.substr(0, error.find('\n'));
      glfwSetWindowTitle(window_, (options_.title + " | error: " + first_line).c_str());
      settled_ = std::min(settled_, kSettleFrames - 1);  // present the last good graph again
    }
    return error;
  }

  // The executor for the swapchain's size: the graph resized when it differs.
  void restart() {
    executor_.reset();
    const VkExtent2D e = presenter_.extent();
    const Extent size{e.width, e.height, 1};
    LoadedConfig& loaded = source_.current();
    if (size.width != loaded.config.output_size.width || size.height != loaded.config.output_size.height) {
      loaded.config.output_size = size;
      resize(loaded.graph, size);
    }
    executor_ = std::make_unique<Executor>(device_, loaded.graph, &loaded.config.scene, options_.compile);
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
  GraphSource source_;
  const ViewOptions& options_;
  WindowEvents& events_;
  vulkan::VulkanDevice device_;
  Presenter presenter_;
  std::unique_ptr<Executor> executor_;
  int rendered_ = 0;
  int settled_ = 0;
  std::vector<uint8_t> shot_;  // the last presented image, for --screenshot
  VkExtent2D shot_extent_{};
  int disk_changes_ = 0;    // changes the hot reload saw
  int waited_changes_ = 0;  // of which the script's wait-change consumed
  struct AbPair {
    std::string pass, a, b;
  } ab_;  // the last toggle_ab: Tab repeats it
};

}  // namespace

int run(LoadedConfig loaded, const ViewOptions& options) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) {
    throw NoDisplay("view: no display to open a window on (DISPLAY is not set); run it on a desktop or under xvfb-run -a");
  }
  GlfwSession glfw;
  WindowEvents events;
  Window window = open_window(loaded.config.output_size, options.title, events);
  std::unique_ptr<vulkan::Context> context = create_context(options);
  bool script_done = true;
  {
    Loop loop(*context, window.get(), std::move(loaded), options, events);
    script_done = loop.run();
  }
  const std::vector<std::string> messages = context->take_validation_messages();
  for (const std::string& m : messages) std::cerr << "validation: " << m << "\n";
  return messages.empty() && script_done ? 0 : 1;
}

}  // namespace volgraph::viewer
