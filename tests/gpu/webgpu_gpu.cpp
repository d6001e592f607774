// The WebGPU backend for the GPU tests (backends.h): Dawn's errors are collected, not
// thrown, so that the test reports all of them.
#include "graph/rhi/webgpu/webgpu_device.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {
namespace {

class WebGpuGpu final : public GpuUnderTest {
 public:
  WebGpuGpu() : device_(webgpu::WebGpuDevice::create({.errors_throw = false})) {}
  rhi::Device& device() override { return *device_; }
  std::vector<std::string> take_messages() override { return device_->take_messages(); }
  std::vector<std::string> finish() override {
    std::vector<std::string> messages = device_->take_messages();
    device_.reset();
    return messages;
  }

 private:
  std::unique_ptr<webgpu::WebGpuDevice> device_;
};

}  // namespace

bool webgpu_built() { return true; }
std::unique_ptr<GpuUnderTest> create_webgpu_gpu() { return std::make_unique<WebGpuGpu>(); }

}  // namespace volgraph::testing
