// The GPU tests' backends (backends.h): Vulkan here, WebGPU in webgpu_gpu.cpp.
#include "tests/gpu/backends.h"

#include "graph/rhi/vulkan/vulkan_device.h"

namespace volgraph::testing {
namespace {

class VulkanGpu final : public GpuUnderTest {
 public:
  VulkanGpu() : context_(vulkan::Context::create({.validation = true})), device_(std::make_unique<vulkan::VulkanDevice>(*context_)) {}
  rhi::Device& device() override { return *device_; }
  std::vector<std::string> finish() override {
    device_.reset();
    return context_->take_validation_messages();
  }

 private:
  std::unique_ptr<vulkan::Context> context_;
  std::unique_ptr<vulkan::VulkanDevice> device_;
};

}  // namespace

std::string_view backend_name(Backend backend) { return backend == Backend::vulkan ? "vulkan" : "webgpu"; }

std::vector<Backend> gpu_backends() {
  if (webgpu_built()) return {Backend::vulkan, Backend::webgpu};
  return {Backend::vulkan};
}

std::string backend_test_name(const ::testing::TestParamInfo<Backend>& info) { return std::string(backend_name(info.param)); }

std::unique_ptr<GpuUnderTest> create_gpu(Backend backend) {
  if (backend == Backend::webgpu) return create_webgpu_gpu();
  return std::make_unique<VulkanGpu>();
}

std::string joined_messages(const std::vector<std::string>& messages) {
  std::string out;
  for (const std::string& m : messages) out += m + "\n";
  return out;
}

}  // namespace volgraph::testing
