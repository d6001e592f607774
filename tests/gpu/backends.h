// The backends every rhi-level GPU test runs on: a test takes its device from here,
// parameterized over {vulkan, webgpu}, and fails on any message the backend's
// validation produced by the end of it — Vulkan: the Khronos layer with synchronization
// validation; WebGPU: Dawn's uncaptured errors (Dawn validates every call).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "graph/rhi/rhi.h"

namespace volgraph::testing {

enum class Backend { vulkan, webgpu };

std::string_view backend_name(Backend backend);
// Vulkan, and WebGPU when the build found Dawn.
std::vector<Backend> gpu_backends();
// For INSTANTIATE_TEST_SUITE_P: "vulkan", "webgpu".
std::string backend_test_name(const ::testing::TestParamInfo<Backend>& info);

// A device under its backend's validation.
class GpuUnderTest {
 public:
  virtual ~GpuUnderTest() = default;
  virtual rhi::Device& device() = 0;
  // The validation messages since the last call (or since the device was made); the
  // device stays.
  virtual std::vector<std::string> take_messages() = 0;
  // Releases the device (the destruction of its objects is validated too) and returns
  // every validation message since the last take_messages.
  virtual std::vector<std::string> finish() = 0;
};

// A device of `backend` for one test. The tests of one process share one device per
// backend, as an application keeps its device across frames: its shader modules and
// pipelines (rhi::Device's caches) are compiled once per process, not once per test
// (lavapipe's and Tint's compiles were most of a GPU test's time). `finish()` returns the
// messages the test caused and hands the device back; a device with any message is
// destroyed instead, so the next test starts on a fresh one. The shared devices are
// destroyed, and their destruction validated, when the tests end (a message then fails
// the run, as a global failure).
std::unique_ptr<GpuUnderTest> create_gpu(Backend backend);

// Made in the backend's file (webgpu_gpu.cpp, or no_webgpu_gpu.cpp without Dawn).
bool webgpu_built();
std::unique_ptr<GpuUnderTest> create_webgpu_gpu();

// One message per line, for EXPECT messages.
std::string joined_messages(const std::vector<std::string>& messages);

// A fixture whose device comes from the backend parameter; TearDown fails the test on
// any validation message.
template <typename Param = Backend>
class OnEachBackend : public ::testing::TestWithParam<Param> {
 protected:
  virtual Backend backend() const = 0;
  void SetUp() override { gpu_ = create_gpu(backend()); }
  void TearDown() override {
    if (!gpu_) return;  // SetUp failed: the test has failed already
    const std::vector<std::string> messages = gpu_->finish();
    EXPECT_TRUE(messages.empty()) << backend_name(backend()) << " validation:\n" << joined_messages(messages);
  }
  rhi::Device& device() { return gpu_->device(); }

  std::unique_ptr<GpuUnderTest> gpu_;
};

}  // namespace volgraph::testing
