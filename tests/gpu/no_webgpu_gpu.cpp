// Without Dawn at build time the GPU tests run on Vulkan only (backends.h).
#include <stdexcept>

#include "tests/gpu/backends.h"

namespace volgraph::testing {

bool webgpu_built() { return false; }
std::unique_ptr<GpuUnderTest> create_webgpu_gpu() { throw std::logic_error("built without Dawn: no WebGPU backend"); }

}  // namespace volgraph::testing
