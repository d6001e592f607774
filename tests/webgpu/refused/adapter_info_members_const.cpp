// AdapterInfo's strings belong to the implementation (freed by wgpuAdapterInfoFreeMembers):
// its members are const to callers, and it moves but does not copy.
#include <utility>
#include <webgpu/webgpu_cpp.h>

wgpu::AdapterInfo take(wgpu::AdapterInfo& info) {
#ifdef REFUSED
  info.device = "llvmpipe";
#endif
  return std::move(info);
}
