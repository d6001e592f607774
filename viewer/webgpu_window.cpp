// The viewer on WebGPU: Dawn's device (the graph's, as `render --backend webgpu` makes it,
// its errors collected rather than thrown: the viewer prints them and exits 1 as Vulkan's
// validation messages) and a wgpu::Surface on the GLFW window's X11 handle. Each frame's
// bytes are written into the surface's texture by a queue write and, for a screenshot,
// copied back out before Present. The overlay is volgraph's CPU renderer of ImGui's lists
// (overlay.h CpuOverlay), drawn into those bytes: Debian's Dear ImGui 1.86 has no WebGPU
// renderer of this API revision (docs/viewer.md "Presenting").
#include <algorithm>
#include <cstring>

#include <GLFW/glfw3.h>

#include "graph/rhi/webgpu/dawn_context.h"
#include "graph/rhi/webgpu/webgpu_device.h"
#include "viewer/overlay.h"
#include "viewer/viewer.h"
#include "viewer/window_backend.h"

// GLFW's X11 accessors (glfw3native.h), declared here rather than included: Xlib's macros
// (None, Success, Status, Bool) would rename webgpu_cpp.h's enumerators.
extern "C" {
struct _XDisplay;
_XDisplay* glfwGetX11Display(void);
unsigned long glfwGetX11Window(GLFWwindow* window);
}

namespace volgraph::viewer {
namespace {

constexpr uint32_t kRowAlignment = 256;  // WebGPU: bytesPerRow of a texture–buffer copy

DeviceError unsupported(const std::string& why) { return DeviceError(DeviceError::Kind::unsupported, "view --backend webgpu: " + why); }

wgpu::Surface create_surface(const webgpu::DawnContext& context, GLFWwindow* window) {
  _XDisplay* display = glfwGetX11Display();
  const unsigned long x11 = glfwGetX11Window(window);
  if (!display || !x11) throw unsupported("the window is not an X11 window (Dawn's surface here takes an Xlib window)");
  wgpu::SurfaceSourceXlibWindow source;
  source.display = display;
  source.window = uint64_t(x11);
  wgpu::SurfaceDescriptor descriptor;
  descriptor.nextInChain = &source;
  descriptor.label = "volgraph view";
  wgpu::Surface surface = context.instance().CreateSurface(&descriptor);
  if (!surface) throw unsupported("Dawn could not make a surface of the window");
  return surface;
}

bool has(wgpu::TextureUsage set, wgpu::TextureUsage usage) { return (set & usage) == usage; }

class WebGpuWindow final : public WindowBackend {
 public:
  WebGpuWindow(GLFWwindow* window, const ViewOptions&)
      : device_(webgpu::WebGpuDevice::create({.errors_throw = false})), surface_(create_surface(device_->context(), window)) {
    choose_configuration();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    recreate({uint32_t(std::max(w, 1)), uint32_t(std::max(h, 1)), 1});
  }
  ~WebGpuWindow() override {
    device_->context().wait_for_queue();
    surface_.Unconfigure();
  }

  rhi::Device& device() override { return *device_; }
  Extent extent() const override { return extent_; }
  bool readable() const override { return has(usage_, wgpu::TextureUsage::CopySrc); }
  bool stale() const override { return stale_; }
  std::unique_ptr<Overlay> make_overlay(GLFWwindow* window) override { return std::make_unique<CpuOverlay>(window); }
  std::vector<std::string> take_messages() override { return device_->take_messages(); }

  void recreate(Extent window) override {
    extent_ = {std::max(window.width, 1u), std::max(window.height, 1u), 1};
    wgpu::SurfaceConfiguration configuration;
    configuration.device = device_->context().device();
    configuration.format = format_;
    configuration.usage = usage_;
    configuration.width = extent_.width;
    configuration.height = extent_.height;
    configuration.alphaMode = alpha_;
    configuration.presentMode = wgpu::PresentMode::Fifo;  // WebGPU's one mode every surface offers
    surface_.Configure(&configuration);
    stale_ = false;
  }

  bool present(const std::vector<uint8_t>& rgba8, std::vector<uint8_t>* presented, const Overlay* overlay) override {
    wgpu::SurfaceTexture target;
    surface_.GetCurrentTexture(&target);
    if (target.status != wgpu::SurfaceGetCurrentTextureStatus::SuccessOptimal &&
        target.status != wgpu::SurfaceGetCurrentTextureStatus::SuccessSuboptimal) {
      stale_ = true;
      return false;
    }
    std::vector<uint8_t> texels = rgba8;
    // The loop hands back the overlay make_overlay made: a CpuOverlay.
    if (overlay) static_cast<const CpuOverlay*>(overlay)->draw(texels, extent_);
    write(target.texture, std::move(texels));
    if (presented && readable()) *presented = read(target.texture);
    surface_.Present();
    stale_ = target.status == wgpu::SurfaceGetCurrentTextureStatus::SuccessSuboptimal;
    return true;
  }

 private:
  // RGBA8 or BGRA8 (the bytes written are sRGB-encoded already, as in a PNG), written by
  // the queue (CopyDst) and read back for screenshots where the surface allows (CopySrc).
  void choose_configuration() {
    wgpu::SurfaceCapabilities capabilities;
    if (!surface_.GetCapabilities(device_->context().adapter(), &capabilities)) throw unsupported("the surface's capabilities are unknown");
    const wgpu::TextureFormat* begin = capabilities.formats;
    const wgpu::TextureFormat* end = begin + capabilities.formatCount;
    if (std::find(begin, end, wgpu::TextureFormat::RGBA8Unorm) != end) {
      format_ = wgpu::TextureFormat::RGBA8Unorm;
    } else if (std::find(begin, end, wgpu::TextureFormat::BGRA8Unorm) != end) {
      format_ = wgpu::TextureFormat::BGRA8Unorm;
    } else {
      throw unsupported("the surface offers no RGBA8Unorm or BGRA8Unorm format");
    }
    if (!has(capabilities.usages, wgpu::TextureUsage::CopyDst)) throw unsupported("the surface's textures cannot be written (no CopyDst usage)");
    usage_ = wgpu::TextureUsage::CopyDst | (capabilities.usages & wgpu::TextureUsage::CopySrc);
    const wgpu::CompositeAlphaMode* alphas = capabilities.alphaModes;
    const bool opaque = std::find(alphas, alphas + capabilities.alphaModeCount, wgpu::CompositeAlphaMode::Opaque) != alphas + capabilities.alphaModeCount;
    alpha_ = opaque ? wgpu::CompositeAlphaMode::Opaque : wgpu::CompositeAlphaMode::Auto;
  }

  bool bgra() const { return format_ == wgpu::TextureFormat::BGRA8Unorm; }

  void write(const wgpu::Texture& texture, std::vector<uint8_t> texels) {
    if (bgra()) swap_red_blue(texels.data(), texels.size() / 4);
    wgpu::TexelCopyTextureInfo destination;
    destination.texture = texture;
    wgpu::TexelCopyBufferLayout layout;
    layout.bytesPerRow = extent_.width * 4;
    layout.rowsPerImage = extent_.height;
    const wgpu::Extent3D size{extent_.width, extent_.height, 1};
    device_->context().queue().WriteTexture(&destination, texels.data(), texels.size(), &layout, &size);
  }

  // The texture as presented, RGBA rows top first.
  std::vector<uint8_t> read(const wgpu::Texture& texture) {
    const uint32_t row = (extent_.width * 4 + kRowAlignment - 1) / kRowAlignment * kRowAlignment;
    const uint64_t bytes = uint64_t(row) * extent_.height;
    const wgpu::Buffer buffer = device_->make_buffer("view read-back", bytes, wgpu::BufferUsage::MapRead | wgpu::BufferUsage::CopyDst);
    const wgpu::Device& device = device_->context().device();
    wgpu::CommandEncoder encoder = device.CreateCommandEncoder();
    wgpu::TexelCopyTextureInfo source;
    source.texture = texture;
    wgpu::TexelCopyBufferInfo destination;
    destination.buffer = buffer;
    destination.layout.bytesPerRow = row;
    destination.layout.rowsPerImage = extent_.height;
    const wgpu::Extent3D size{extent_.width, extent_.height, 1};
    encoder.CopyTextureToBuffer(&source, &destination, &size);
    const wgpu::CommandBuffer commands = encoder.Finish();
    device_->context().queue().Submit(1, &commands);
    bool mapped = false;
    device_->context().wait(buffer.MapAsync(wgpu::MapMode::Read, 0, bytes, wgpu::CallbackMode::WaitAnyOnly,
                                            [&mapped](wgpu::MapAsyncStatus status, wgpu::StringView) {
                                              mapped = status == wgpu::MapAsyncStatus::Success;
                                            }),
                            "the window's read-back");
    if (!mapped) throw DeviceError(DeviceError::Kind::other, "Dawn: the window's read-back buffer could not be mapped");
    const auto* mapped_bytes = static_cast<const uint8_t*>(buffer.GetConstMappedRange(0, bytes));
    std::vector<uint8_t> out(size_t(extent_.width) * extent_.height * 4);
    for (uint32_t y = 0; y < extent_.height; ++y) {
      std::memcpy(out.data() + size_t(y) * extent_.width * 4, mapped_bytes + size_t(y) * row, size_t(extent_.width) * 4);
    }
    buffer.Unmap();
    if (bgra()) swap_red_blue(out.data(), out.size() / 4);
    return out;
  }

  std::unique_ptr<webgpu::WebGpuDevice> device_;
  wgpu::Surface surface_;
  wgpu::TextureFormat format_ = wgpu::TextureFormat::Undefined;
  wgpu::TextureUsage usage_ = wgpu::TextureUsage::CopyDst;
  wgpu::CompositeAlphaMode alpha_ = wgpu::CompositeAlphaMode::Auto;
  Extent extent_{};
  bool stale_ = false;
};

}  // namespace

std::unique_ptr<WindowBackend> make_webgpu_window(GLFWwindow* window, const ViewOptions& options) {
  return std::make_unique<WebGpuWindow>(window, options);
}

}  // namespace volgraph::viewer
