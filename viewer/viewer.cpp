#include "viewer/viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <chrono>
#include <map>
#include <memory>
#include <filesystem>
#include <functional>
#include <span>
#include <array>
#include <thread>
#include <vector>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "graph/execute/executor.h"
#include "graph/plan_report.h"
#include "graph/probe.h"
#include "physics/srgb.h"
#include "tools/image_io.h"
#include "tools/output_files.h"
#include "viewer/capture.h"
#include "viewer/overlay.h"
#include "viewer/shader_watch.h"
#include "viewer/window_backend.h"
#include <iomanip>
#include <optional>
#include <sstream>

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
  bool overlay = false;  // F1: the overlay shown or hidden
  bool capture = false;  // F12: PNG + EXR + config of the frame
  bool input = false;    // the mouse moved or a button or key was pressed: the overlay redraws
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
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan or WebGPU presents, not OpenGL
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
    WindowEvents& events = *static_cast<WindowEvents*>(glfwGetWindowUserPointer(w));
    events.input = true;
    if (action != GLFW_PRESS) return;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(w, GLFW_TRUE);
    if (key == GLFW_KEY_R) events.reload = true;
    if (key == GLFW_KEY_TAB) events.ab = true;
    if (key == GLFW_KEY_F1) events.overlay = true;
    if (key == GLFW_KEY_F12) events.capture = true;
  });
  // Any mouse input redraws (the overlay's widgets answer it; ImGui chains these callbacks).
  glfwSetCursorPosCallback(window.get(), [](GLFWwindow* w, double, double) { static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->input = true; });
  glfwSetMouseButtonCallback(window.get(), [](GLFWwindow* w, int, int, int) { static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->input = true; });
  glfwSetScrollCallback(window.get(), [](GLFWwindow* w, double, double) { static_cast<WindowEvents*>(glfwGetWindowUserPointer(w))->input = true; });
  return window;
}

Extent framebuffer_extent(GLFWwindow* window) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window, &w, &h);
  return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0)), 1};
}

// A texture as the resource view shows it: slice `slice` of a 3D one, scaled by 2^exposure,
// sampled at the nearest texel for each of `size`'s pixels, sRGB-encoded to 8 bits, opaque;
// NaN and infinities magenta, so a pass that leaks them shows where.
std::vector<uint8_t> resource_view(const Texels& t, Extent size, int slice, double exposure) {
  std::vector<uint8_t> out(size_t(size.width) * size.height * 4, 255);
  if (t.width == 0 || t.height == 0) return out;
  const size_t z = size_t(std::clamp(slice, 0, int(t.depth) - 1));
  const float scale = float(std::exp2(exposure));
  for (uint32_t y = 0; y < size.height; ++y) {
    const size_t ty = size_t(y) * t.height / size.height;
    for (uint32_t x = 0; x < size.width; ++x) {
      const size_t tx = size_t(x) * t.width / size.width;
      const float* texel = &t.rgba[((z * t.height + ty) * t.width + tx) * 4];
      uint8_t* pixel = &out[(size_t(y) * size.width + x) * 4];
      const bool finite = std::isfinite(texel[0]) && std::isfinite(texel[1]) && std::isfinite(texel[2]);
      for (int c = 0; c < 3; ++c) {
        pixel[c] = finite ? uint8_t(std::lround(physics::srgb_encode(texel[c] * scale) * 255.0f)) : (c == 1 ? 0 : 255);
      }
    }
  }
  return out;
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

void write_screenshot(const std::string& path, Extent extent, const std::vector<uint8_t>& rgba8) {
  OutputFiles files;
  files.stage(path, "--screenshot", encode_png_rgba8(extent.width, extent.height, rgba8));
  files.commit();
}

// A JSON number as the loader reads it back (the control API takes JSON text).
std::string json_number(double v) {
  std::ostringstream out;
  out << std::setprecision(9) << v;
  return out.str();
}

Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 operator*(const Vec3& a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }
double length(const Vec3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Vec3 normalized(const Vec3& a) { return a * (1.0 / std::max(length(a), 1e-12)); }
Vec3 cross(const Vec3& a, const Vec3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

constexpr double kPi = 3.14159265358979323846;
// The direction a sun light travels for a sun at azimuth `az` (degrees from +z toward +x)
// and elevation `el` (degrees above the y = 0 plane): the opposite of the way to the sun.
Vec3 sun_travel(double az, double el) {
  const double a = az * kPi / 180, e = el * kPi / 180;
  return {-std::cos(e) * std::sin(a), -std::sin(e), -std::cos(e) * std::cos(a)};
}

// The scene's sun: the atmosphere's sun light, else its first directional light (-1: none).
int sun_index(const Scene& scene) {
  if (scene.atmosphere && scene.atmosphere->sun_light >= 0) return scene.atmosphere->sun_light;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    if (scene.lights[i].type == LightType::directional) return int(i);
  }
  return -1;
}

// The loop: one frame of the graph, its output copied into the swapchain and presented;
// a resize recompiles the graph at the new size (resize(), no config reload); idle
// (glfwWaitEventsTimeout) once a static scene has settled.
class Loop {
 public:
  Loop(WindowBackend& backend, GLFWwindow* window, LoadedConfig loaded, const ViewOptions& options, WindowEvents& events)
      : backend_(backend), window_(window),
        source_(options.config, *options.registry, options.overrides, options.compile, std::move(loaded)),
        options_(options), events_(events),
        shaders_(options.shaders.empty() ? std::filesystem::path(VOLGRAPH_SHADER_SOURCE_DIR) : std::filesystem::path(options.shaders),
                 VOLGRAPH_GLSLANG) {
    if (options.overlay) overlay_ = backend.make_overlay(window);
    overlay_shown_ = overlay_ != nullptr;
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
  // The resource view: "PASS.SLOT" (graph/probe.h, what `render --dump` reads) shown in
  // place of the output, or "output" for the output again. A new executor keeps that
  // version to the frame's end; a name the graph refuses keeps the current view.
  std::string show(const std::string& name) {
    const std::string next = name == "output" ? "" : name;
    if (!next.empty()) {
      try {
        find_probe(source_.current().graph, next, {"<view>", "show " + next, 0});
      } catch (const ConfigError& e) {
        return applied(e.what());
      }
    }
    shown_ = next;
    return applied("");
  }
  // The resource view's exposure (EV: the texels times 2^EV) and 3D slice.
  void set_view_exposure(double ev) {
    view_exposure_ = ev;
    settled_ = std::min(settled_, kSettleFrames - 1);
  }
  void set_view_slice(int slice) {
    view_slice_ = slice;
    settled_ = std::min(settled_, kSettleFrames - 1);
  }

  // The fly camera: the scene's camera moved in place (passes read the scene every frame;
  // their cache keys hash it), kept over reloads.
  void set_camera(const Vec3& position, const Vec3& target) {
    camera_ = std::make_pair(position, target);
    apply_view_state();
  }
  // The sun (the scene's first directional light) at azimuth/elevation in degrees, kept over reloads.
  void set_sun(double azimuth, double elevation) {
    sun_ = std::make_pair(azimuth, elevation);
    apply_view_state();
  }
  // The last presented image (one frame first when none was presented yet).
  void screenshot(const std::string& path) {
    if (shot_.empty()) frames(1);
    write_screenshot(path, shot_extent_, shot_);
  }

  // The capture (capture.h): PREFIX.png, .exr and .json, written together or not at all,
  // of the last frame (one frame first when none was rendered since the last change).
  void capture(const std::string& prefix) {
    if (frames_since_restart_ == 0) frames(1);
    CaptureState state;
    state.config = options_.config;
    state.overrides = source_.overrides();
    const Scene& scene = source_.current().config.scene;
    state.camera = scene.camera;
    const int sun = sun_index(scene);
    if (sun >= 0 && !scene.lights[size_t(sun)].name.empty()) state.sun = scene.lights[size_t(sun)];
    state.size = {last_output_.width, last_output_.height, 1};
    state.frames = frames_since_restart_;
    const std::string json = prefix + ".json";
    const Image linear{last_output_.width, last_output_.height, last_output_.rgba};
    OutputFiles files;
    files.stage(prefix + ".png", "capture", encode_png_rgba8(linear.width, linear.height, srgb8(last_output_)));
    files.stage(prefix + ".exr", "capture", encode_image(linear, ImageFormat::exr));
    const std::string text = capture_config(state, json);
    files.stage(json, "capture", std::as_bytes(std::span(text.data(), text.size())));
    files.commit();
    std::cout << "view: captured " << prefix << ".png, .exr, .json; the same image: " << capture_render_command(json, state) << std::endl;
    if (sun >= 0 && !state.sun && sun_) std::cerr << "view: capture: the sun has no name, so its direction is not in " << json << "\n";
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
    auto last = std::chrono::steady_clock::now();
    while (!glfwWindowShouldClose(window_)) {
      const auto now = std::chrono::steady_clock::now();
      fly(std::min(std::chrono::duration<double>(now - last).count(), 0.1));
      last = now;
      handle_keys();
      poll_files();
      if (events.resized || backend_.stale()) {
        events.resized = false;
        if (!resize_to_window()) continue;
      }
      if (events.exposed || (events.input && overlay_shown_)) settled_ = std::min(settled_, kSettleFrames - 1);  // present again
      events.exposed = events.input = false;
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
    if (c.verb == "capture") capture(a[0]);
    if (c.verb == "show") show(a[0]);
    if (c.verb == "exposure") set_view_exposure(std::stod(a[0]));
    if (c.verb == "slice") set_view_slice(std::stoi(a[0]));
    if (c.verb == "camera" || c.verb == "sun") {
      std::vector<double> v;
      for (const std::string& w : a) v.push_back(std::stod(w));
      if (c.verb == "camera") set_camera({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
      if (c.verb == "sun") set_sun(v[0], v[1]);
      restart();  // a fresh frame history: the script's next frames are `render`'s of that camera
    }
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
      if ((events_.resized || backend_.stale()) && !resize_to_window()) continue;
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
    if (events_.capture) capture(next_capture_prefix());
    if (events_.ab && !ab_.pass.empty()) toggle_ab(ab_.pass, ab_.a, ab_.b);
    if (events_.overlay && overlay_) {
      overlay_shown_ = !overlay_shown_;
      executor_->set_gpu_timing(overlay_shown_);
      settled_ = std::min(settled_, kSettleFrames - 1);
    }
    events_.reload = events_.ab = events_.overlay = events_.capture = false;
    if (pending_) {  // an edit made in the overlay, applied between frames
      auto edit = std::move(pending_);
      pending_ = nullptr;
      edit();
    }
  }

  // WASD moves the camera along its view and right axes; a right-button drag turns it.
  void fly(double dt) {
    if (overlay_ && overlay_shown_ && (overlay_->wants_keyboard() || overlay_->wants_mouse())) {
      glfwGetCursorPos(window_, &cursor_[0], &cursor_[1]);
      return;
    }
    const Camera& c = source_.current().config.scene.camera;
    const Vec3 forward = normalized(c.target - c.position), right = normalized(cross(forward, c.up));
    const double distance = std::max(length(c.target - c.position), 1e-3);
    const double step = std::max(distance, 1.0) * dt;  // about the target's distance a second
    Vec3 move{0, 0, 0};
    if (glfwGetKey(window_, GLFW_KEY_W) == GLFW_PRESS) move = move + forward * step;
    if (glfwGetKey(window_, GLFW_KEY_S) == GLFW_PRESS) move = move - forward * step;
    if (glfwGetKey(window_, GLFW_KEY_D) == GLFW_PRESS) move = move + right * step;
    if (glfwGetKey(window_, GLFW_KEY_A) == GLFW_PRESS) move = move - right * step;
    double x = 0, y = 0;
    glfwGetCursorPos(window_, &x, &y);
    const double dx = x - cursor_[0], dy = y - cursor_[1];
    cursor_ = {x, y};
    Vec3 look = forward;
    if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && (dx != 0 || dy != 0)) {
      const double yaw = -dx * 0.005, pitch = -dy * 0.005;  // radians per pixel
      const Vec3 up = normalized(cross(right, forward));
      look = normalized(forward * std::cos(yaw) + right * std::sin(yaw));
      look = normalized(look * std::cos(pitch) + up * std::sin(pitch));
      if (std::abs(look[0] * c.up[0] + look[1] * c.up[1] + look[2] * c.up[2]) > 0.99) look = forward;  // not through the pole
    }
    if (length(move) == 0 && look == forward) return;
    set_camera(c.position + move, c.position + move + look * distance);
  }

  // The viewer's camera and sun on the current scene (after every reload).
  void apply_view_state() {
    Scene& scene = source_.current().config.scene;
    if (camera_) {
      scene.camera.position = camera_->first;
      scene.camera.target = camera_->second;
    }
    const int sun = sun_index(scene);
    if (sun_ && sun >= 0) scene.lights[size_t(sun)].direction = sun_travel(sun_->first, sun_->second);
    settled_ = std::min(settled_, 0);
  }

  // The overlay's panel: times, the plan's figures, the last error, the passes' variants
  // and parameters (edits go through set_variant / set_param, checked as before), the
  // A/B pair and the sun.
  void draw_panel() {
    const Extent e = backend_.extent();
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::min(380.0f, 0.5f * float(e.width)), float(e.height)), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("volgraph", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    if (!last_error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", last_error_.c_str());
    draw_times();
    draw_plan();
    draw_ab();
    draw_resource_view();
    draw_sun();
    draw_passes();
    ImGui::End();
  }

  double total_gpu_ms() const {
    double sum = 0;
    for (const PassTiming& t : executor_->timings()) sum += t.gpu_ms;
    return sum;
  }

  void draw_times() {
    if (!ImGui::CollapsingHeader("GPU times", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Text("frame %.3f ms (passes), %.3f ms (submit to done)", total_gpu_ms(), executor_->frame_wall_ms());
    for (const PassTiming& t : executor_->timings()) {
      ImGui::Text("%8.3f ms  %s%s", t.gpu_ms, t.pass.c_str(), t.cached ? " (cached)" : "");
    }
  }

  void draw_plan() {
    if (!ImGui::CollapsingHeader("Plan", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const Plan& plan = executor_->plan();
    ImGui::Text("transient: %s aliased, %s unaliased", bytes_text(plan.memory.aliased_bytes).c_str(),
                bytes_text(plan.memory.unaliased_bytes).c_str());
    ImGui::Text("lower bound %s, persistent %s", bytes_text(plan.memory.lower_bound_bytes).c_str(),
                bytes_text(plan.memory.persistent_bytes).c_str());
    ImGui::Text("%zu passes, %zu culled, %zu barriers", plan.order.size(), plan.culled.size(), plan.barriers.size());
  }

  void draw_ab() {
    if (!ImGui::CollapsingHeader("A/B (Tab)")) return;
    const Graph& graph = source_.current().graph;
    if (ImGui::BeginCombo("pass", ab_.pass.c_str())) {
      for (const GraphPass& p : graph.passes) {
        if (p.step != 0 || p.decl->variants.size() < 2) continue;
        if (ImGui::Selectable(p.name.c_str(), p.name == ab_.pass)) {
          ab_ = {p.name, p.decl->variants[0].name, p.decl->variants[1].name};
        }
      }
      ImGui::EndCombo();
    }
    const GraphPass* pass = find_pass(ab_.pass);
    if (!pass) return;
    variant_combo("A", *pass, ab_.a);
    variant_combo("B", *pass, ab_.b);
    const std::string now = pass->decl->variants[pass->variant].name;
    ab_times_[now] = total_gpu_ms();
    if (ImGui::Button("toggle (Tab)")) events_.ab = true;
    ImGui::Text("A %s: %.3f ms   B %s: %.3f ms   (showing %s)", ab_.a.c_str(), ab_times_[ab_.a], ab_.b.c_str(), ab_times_[ab_.b],
                now.c_str());
  }

  // Any texture a pass writes, shown in place of the output (3D ones by slice), with exposure.
  void draw_resource_view() {
    if (!ImGui::CollapsingHeader("Resources")) return;
    const std::string current = shown_.empty() ? "output" : shown_;
    if (ImGui::BeginCombo("show", current.c_str())) {
      if (ImGui::Selectable("output", shown_.empty())) pending_ = [this] { show("output"); };
      for (const std::string& name : probe_names_) {
        if (ImGui::Selectable(name.c_str(), name == shown_)) pending_ = [this, name] { show(name); };
      }
      ImGui::EndCombo();
    }
    if (shown_.empty()) return;
    ImGui::Text("%u x %u x %u", shown_size_.width, shown_size_.height, shown_size_.depth);
    float ev = float(view_exposure_);
    if (ImGui::SliderFloat("exposure", &ev, -16, 16, "%.1f EV")) set_view_exposure(ev);
    int slice = view_slice_;
    if (shown_size_.depth > 1 && ImGui::SliderInt("slice", &slice, 0, int(shown_size_.depth) - 1)) set_view_slice(slice);
  }

  void variant_combo(const char* label, const GraphPass& pass, std::string& chosen) {
    if (!ImGui::BeginCombo(label, chosen.c_str())) return;
    for (const VariantDecl& v : pass.decl->variants) {
      if (ImGui::Selectable(v.name.c_str(), v.name == chosen)) chosen = v.name;
    }
    ImGui::EndCombo();
  }

  const GraphPass* find_pass(const std::string& name) {
    for (const GraphPass& p : source_.current().graph.passes) {
      if (p.name == name && p.step == 0) return &p;
    }
    return nullptr;
  }

  void draw_sun() {
    Scene& scene = source_.current().config.scene;
    const int sun = sun_index(scene);
    if (sun < 0 || !ImGui::CollapsingHeader("Sun", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const Vec3 to_sun = normalized(scene.lights[size_t(sun)].direction * -1.0);
    float az = float(std::atan2(to_sun[0], to_sun[2]) * 180 / kPi), el = float(std::asin(std::clamp(to_sun[1], -1.0, 1.0)) * 180 / kPi);
    bool changed = ImGui::SliderFloat("azimuth", &az, -180, 180, "%.1f deg");
    changed |= ImGui::SliderFloat("elevation", &el, -10, 90, "%.1f deg");
    if (changed) set_sun(az, el);
  }

  void draw_passes() {
    if (!ImGui::CollapsingHeader("Passes", ImGuiTreeNodeFlags_DefaultOpen)) return;
    for (const GraphPass& p : source_.current().graph.passes) {
      if (p.step != 0 || !ImGui::TreeNode(p.name.c_str(), "%s (%s)", p.name.c_str(), p.decl->name.c_str())) continue;
      std::string variant = p.decl->variants[p.variant].name;
      if (p.decl->variants.size() > 1) {
        const std::string before = variant;
        variant_combo("variant", p, variant);
        if (variant != before) pending_ = [this, pass = p.name, variant] { set_variant(pass, variant); };
      }
      for (size_t i = 0; i < p.decl->params.size(); ++i) {
        const ParamValue value = i < p.params.size() ? p.params[i] : p.decl->params[i].default_value;
        param_widget(p.name, p.decl->params[i], value);
      }
      ImGui::TreePop();
    }
  }

  // One parameter's widget, with the declaration's range and unit; a finished edit goes
  // through set_param (the loader checks it as `render --set` does).
  void param_widget(const std::string& pass, const ParamDecl& d, const ParamValue& value) {
    std::string json;
    const std::string format = "%.4g" + (d.unit.empty() ? "" : " " + d.unit);
    ImGui::PushID(d.name.c_str());
    if (const bool* b = std::get_if<bool>(&value)) {
      bool v = *b;
      if (ImGui::Checkbox(d.name.c_str(), &v)) json = v ? "true" : "false";
    } else if (const int64_t* n = std::get_if<int64_t>(&value)) {
      int v = int(*n);
      if (d.min < d.max) {
        ImGui::SliderInt(d.name.c_str(), &v, int(d.min), int(d.max), ("%d" + (d.unit.empty() ? "" : " " + d.unit)).c_str());
      } else {  // no declared range: a plain input
        ImGui::InputInt(d.name.c_str(), &v);
      }
      if (ImGui::IsItemDeactivatedAfterEdit()) json = std::to_string(v);
    } else if (const double* x = std::get_if<double>(&value)) {
      float v = float(*x);
      if (d.min < d.max) {
        ImGui::SliderFloat(d.name.c_str(), &v, float(d.min), float(d.max), format.c_str());
      } else {  // no declared range: a plain input
        ImGui::InputFloat(d.name.c_str(), &v, 0, 0, format.c_str());
      }
      if (ImGui::IsItemDeactivatedAfterEdit()) json = json_number(v);
    } else if (const auto* a = std::get_if<std::array<double, 3>>(&value)) {
      float v[3] = {float((*a)[0]), float((*a)[1]), float((*a)[2])};
      ImGui::SliderFloat3(d.name.c_str(), v, float(d.min), float(d.max), format.c_str());
      if (ImGui::IsItemDeactivatedAfterEdit()) json = "[" + json_number(v[0]) + "," + json_number(v[1]) + "," + json_number(v[2]) + "]";
    } else if (const std::string* c = std::get_if<std::string>(&value)) {
      if (ImGui::BeginCombo(d.name.c_str(), c->c_str())) {
        for (const std::string& choice : d.choices) {
          if (ImGui::Selectable(choice.c_str(), choice == *c)) json = "\"" + choice + "\"";
        }
        ImGui::EndCombo();
      }
    }
    if (!d.doc.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", d.doc.c_str());
    ImGui::PopID();
    if (!json.empty()) pending_ = [this, pass, name = d.name, json] { set_param(pass, name, json); };
  }

  // F12's files: volgraph_capture_N in the working directory, N the first number free.
  static std::string next_capture_prefix() {
    for (int n = 1;; ++n) {
      const std::string prefix = "volgraph_capture_" + std::to_string(n);
      if (!std::filesystem::exists(prefix + ".json") && !std::filesystem::exists(prefix + ".png")) return prefix;
    }
  }

  // Hot reload: the config or an include changed on disk; a shader source changed.
  void poll_files() {
    if (source_.files_changed()) {
      ++disk_changes_;
      reload();
    }
    poll_shaders();
  }

  // The shaders that changed (or include a file that did), compiled again and handed to
  // the device: the graph is rebuilt with them. A compile error, or a graph the new
  // shaders do not fit (bindings checked at setup), keeps the last good shaders and frame.
  void poll_shaders() {
    ShaderChanges changes = shaders_.poll();
    if (!changes.any()) return;
    ++disk_changes_;
    if (!changes.error.empty()) {
      applied(changes.error);
      return;
    }
    rhi::Device& device = backend_.device();
    std::vector<std::pair<std::string, std::vector<uint32_t>>> before;
    for (CompiledShader& c : changes.compiled) {
      const std::span<const uint32_t> old = device.replaced_shader(c.name);
      before.push_back({c.name, std::vector<uint32_t>(old.begin(), old.end())});
      device.replace_shader(c.name, std::move(c.spirv));
    }
    try {
      restart();
      std::cerr << "view: shaders reloaded:";
      for (const auto& [name, old] : before) std::cerr << " " << name;
      std::cerr << "\n";
      applied("");
    } catch (const std::exception& e) {
      for (auto& [name, old] : before) {
        if (old.empty()) {
          device.restore_shader(name);
        } else {
          device.replace_shader(name, std::move(old));
        }
      }
      restart();
      applied(std::string("view: the reloaded shaders do not fit the graph; the last good ones run on:\n") + e.what());
    }
  }

  // After a change: the new graph runs, or the refusal is shown (title) and printed once.
  std::string applied(const std::string& error) {
    last_error_ = error;
    if (error.empty()) {
      apply_view_state();
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
    const Extent size = backend_.extent();
    LoadedConfig& loaded = source_.current();
    if (size.width != loaded.config.output_size.width || size.height != loaded.config.output_size.height) {
      loaded.config.output_size = size;
      resize(loaded.graph, size);
    }
    const Graph* graph = &loaded.graph;
    probe_names_ = probe_names(loaded.graph);
    if (!shown_.empty()) {
      probed_graph_ = loaded.graph;
      try {
        shown_resource_ = probe_slot(probed_graph_, shown_, {"<view>", "show " + shown_, 0});
        graph = &probed_graph_;
      } catch (const ConfigError& e) {  // a reload took the pass or slot away: the output again
        std::cerr << e.what() << "\n";
        shown_.clear();
      }
    }
    executor_ = std::make_unique<Executor>(backend_.device(), *graph, &loaded.config.scene, options_.compile);
    executor_->set_gpu_timing(overlay_shown_);  // time stamps only while the overlay shows the pass times
    settled_ = 0;
    frames_since_restart_ = 0;
  }

  // False while the window is minimised (nothing to present to).
  bool resize_to_window() {
    const Extent window = framebuffer_extent(window_);
    if (window.width == 0 || window.height == 0) {
      glfwWaitEvents();
      return false;
    }
    backend_.recreate(window);
    restart();
    return true;
  }

  bool frame(bool screenshot) {
    executor_->run_frame();
    ++frames_since_restart_;
    last_output_ = executor_->read_output(0);
    std::vector<uint8_t> texels;
    if (shown_.empty()) {
      texels = srgb8(last_output_);
    } else {
      const Texels shown = executor_->read_texture(shown_resource_);
      shown_size_ = {shown.width, shown.height, shown.depth};
      texels = resource_view(shown, {last_output_.width, last_output_.height, 1}, view_slice_, view_exposure_);
    }
    std::vector<uint8_t>* read_back = screenshot && backend_.readable() ? &shot_ : nullptr;
    const Overlay* drawn = nullptr;
    if (overlay_ && overlay_shown_) {
      overlay_->begin_frame();
      draw_panel();
      overlay_->end_frame();
      drawn = overlay_.get();
    }
    if (!backend_.present(texels, read_back, drawn)) return false;
    if (screenshot) shot_extent_ = backend_.extent();
    if (screenshot && !read_back) shot_ = texels;  // swapchain images not copyable from: the bytes presented
    ++rendered_;
    ++settled_;
    return true;
  }

  WindowBackend& backend_;
  GLFWwindow* window_;
  GraphSource source_;
  const ViewOptions& options_;
  WindowEvents& events_;
  ShaderWatch shaders_;               // the shader sources (hot reload)
  std::unique_ptr<Overlay> overlay_;  // null with --no-overlay
  bool overlay_shown_ = false;        // F1
  std::function<void()> pending_;     // an overlay edit, applied between frames
  std::string last_error_;            // the last refused change's message, shown in the overlay
  std::optional<std::pair<Vec3, Vec3>> camera_;      // set_camera's position and target
  std::optional<std::pair<double, double>> sun_;     // set_sun's azimuth and elevation (degrees)
  std::array<double, 2> cursor_{};                   // the mouse at the last fly() (pixels)
  std::map<std::string, double> ab_times_;           // the frame's GPU ms per variant of the A/B pass
  std::unique_ptr<Executor> executor_;
  int rendered_ = 0;
  int frames_since_restart_ = 0;  // frames of the current executor (a capture's --frames)
  Texels last_output_;            // the last frame's output, linear (for a capture)
  std::string shown_;             // the resource view's PASS.SLOT ("" for the output)
  uint32_t shown_resource_ = 0;   // its graph resource in probed_graph_
  Extent shown_size_{};           // its size at the last frame
  Graph probed_graph_;            // the graph with the shown slot kept to the frame's end (the executor's)
  std::vector<std::string> probe_names_;  // what the view can show (graph/probe.h)
  double view_exposure_ = 0;      // EV
  int view_slice_ = 0;            // of a 3D texture
  int settled_ = 0;
  std::vector<uint8_t> shot_;  // the last presented image, for --screenshot
  Extent shot_extent_{};
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
  const bool webgpu = options.backend == "webgpu";
  std::unique_ptr<WindowBackend> backend = webgpu ? make_webgpu_window(window.get(), options) : make_vulkan_window(window.get(), options);
  bool script_done = true;
  {
    Loop loop(*backend, window.get(), std::move(loaded), options, events);
    script_done = loop.run();
  }
  const std::vector<std::string> messages = backend->take_messages();
  for (const std::string& m : messages) std::cerr << (webgpu ? "dawn: " : "validation: ") << m << "\n";
  return messages.empty() && script_done ? 0 : 1;
}

}  // namespace volgraph::viewer
