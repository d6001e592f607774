// The GPU tests' backends (backends.h): Vulkan here, WebGPU in webgpu_gpu.cpp.
#include "tests/gpu/backends.h"

#include <array>

#include "graph/rhi/vulkan/vulkan_device.h"

namespace volgraph::testing {
namespace {

class VulkanGpu final : public GpuUnderTest {
 public:
  VulkanGpu() : context_(vulkan::Context::create({.validation = true})), device_(std::make_unique<vulkan::VulkanDevice>(*context_)) {}
  rhi::Device& device() override { return *device_; }
  std::vector<std::string> take_messages() override { return context_->take_validation_messages(); }
  std::vector<std::string> finish() override {
    device_.reset();
    return context_->take_validation_messages();
  }

 private:
  std::unique_ptr<vulkan::Context> context_;
  std::unique_ptr<vulkan::VulkanDevice> device_;
};

// The devices the tests of this process share (create_gpu), one per backend; a GoogleTest
// environment, so that the last ones are destroyed and their messages reported before
// the run's result is decided.
class SharedGpus final : public ::testing::Environment {
 public:
  std::unique_ptr<GpuUnderTest> take(Backend backend) { return std::move(kept_[size_t(backend)]); }
  void keep(Backend backend, std::unique_ptr<GpuUnderTest> gpu) { kept_[size_t(backend)] = std::move(gpu); }
  void TearDown() override {
    for (size_t b = 0; b < kept_.size(); ++b) {
      if (!kept_[b]) continue;
      const std::vector<std::string> messages = kept_[b]->finish();
      kept_[b].reset();
      EXPECT_TRUE(messages.empty()) << backend_name(Backend(b)) << " validation, destroying the device the tests shared:\n"
                                    << joined_messages(messages);
    }
  }

 private:
  std::array<std::unique_ptr<GpuUnderTest>, 2> kept_;
};

// The process's shared devices: registered with GoogleTest on first use (it owns and
// deletes the environment at exit).
SharedGpus& shared_gpus() {
  static SharedGpus* const shared = static_cast<SharedGpus*>(::testing::AddGlobalTestEnvironment(new SharedGpus));
  return *shared;
}

// A device of its own, destroyed by finish().
std::unique_ptr<GpuUnderTest> create_own_gpu(Backend backend) {
  if (backend == Backend::webgpu) return create_webgpu_gpu();
  return std::make_unique<VulkanGpu>();
}

// A shared device lent to one test: finish() hands it back when the test caused no
// message, destroys it otherwise.
class LentGpu final : public GpuUnderTest {
 public:
  LentGpu(Backend backend, std::unique_ptr<GpuUnderTest> gpu) : backend_(backend), gpu_(std::move(gpu)) {}
  rhi::Device& device() override { return gpu_->device(); }
  std::vector<std::string> take_messages() override { return gpu_->take_messages(); }
  std::vector<std::string> finish() override {
    std::vector<std::string> messages = gpu_->take_messages();
    if (messages.empty()) {
      shared_gpus().keep(backend_, std::move(gpu_));
      return messages;
    }
    for (std::string& m : gpu_->finish()) messages.push_back(std::move(m));
    gpu_.reset();
    return messages;
  }

 private:
  Backend backend_;
  std::unique_ptr<GpuUnderTest> gpu_;
};

}  // namespace

std::string_view backend_name(Backend backend) { return backend == Backend::vulkan ? "vulkan" : "webgpu"; }

std::vector<Backend> gpu_backends() {
  if (webgpu_built()) return {Backend::vulkan, Backend::webgpu};
  return {Backend::vulkan};
}

std::string backend_test_name(const ::testing::TestParamInfo<Backend>& info) { return std::string(backend_name(info.param)); }

std::unique_ptr<GpuUnderTest> create_gpu(Backend backend) {
  std::unique_ptr<GpuUnderTest> gpu = shared_gpus().take(backend);
  if (!gpu) gpu = create_own_gpu(backend);
  return std::make_unique<LentGpu>(backend, std::move(gpu));
}

std::string joined_messages(const std::vector<std::string>& messages) {
  std::string out;
  for (const std::string& m : messages) out += m + "\n";
  return out;
}

}  // namespace volgraph::testing
