// adapter_choice_test.cpp — which Dawn adapters volgraph renders on by default
// (graph/rhi/webgpu/adapter_choice.h), from the AdapterInfo values Dawn reports: on this
// machine lavapipe is Vulkan / CPU / "llvmpipe (LLVM 15.0.6, 256 bits)", and with no
// Vulkan driver Dawn offers Null / CPU / "Null backend".
#include <gtest/gtest.h>

#include "graph/rhi/webgpu/adapter_choice.h"

namespace {

using volgraph::webgpu::fallback_adapter_reason;

TEST(WebGpuAdapterChoice, LavapipeIsRenderedOn) {
  EXPECT_EQ(fallback_adapter_reason(wgpu::BackendType::Vulkan, wgpu::AdapterType::CPU, "llvmpipe (LLVM 15.0.6, 256 bits)"),
            std::nullopt);
}

TEST(WebGpuAdapterChoice, AGpuIsRenderedOn) {
  EXPECT_EQ(fallback_adapter_reason(wgpu::BackendType::Vulkan, wgpu::AdapterType::DiscreteGPU, "AMD Radeon"), std::nullopt);
  EXPECT_EQ(fallback_adapter_reason(wgpu::BackendType::Vulkan, wgpu::AdapterType::IntegratedGPU, "Intel"), std::nullopt);
}

TEST(WebGpuAdapterChoice, TheNullBackendIsRefused) {
  const auto reason = fallback_adapter_reason(wgpu::BackendType::Null, wgpu::AdapterType::CPU, "Null backend");
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("Null backend"), std::string::npos) << *reason;
}

TEST(WebGpuAdapterChoice, ACpuFallbackOtherThanLavapipeIsRefused) {
  const auto reason = fallback_adapter_reason(wgpu::BackendType::Vulkan, wgpu::AdapterType::CPU, "SwiftShader Device");
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("SwiftShader Device"), std::string::npos) << *reason;
}

}  // namespace
