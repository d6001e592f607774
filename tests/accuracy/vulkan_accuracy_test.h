// The accuracy tests' fixture: the built-in passes registered and Vulkan (lavapipe) under
// the Khronos validation layer, any message failing the test.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "graph/registry.h"
#include "passes/passes.h"
#include "tests/gpu/backends.h"

namespace volgraph::testing {

class VulkanAccuracyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    register_builtin_passes(registry_);
    gpu_ = create_gpu(Backend::vulkan);
  }
  void TearDown() override {
    const std::vector<std::string> messages = gpu_->finish();
    EXPECT_TRUE(messages.empty()) << "vulkan validation:\n" << joined_messages(messages);
  }
  PassRegistry registry_;
  std::unique_ptr<GpuUnderTest> gpu_;
};

}  // namespace volgraph::testing
