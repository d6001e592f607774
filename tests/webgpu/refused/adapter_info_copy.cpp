// AdapterInfo owns what the implementation allocated: moved, never copied.
#include <utility>
#include <webgpu/webgpu_cpp.h>

void keep(wgpu::AdapterInfo& info, wgpu::AdapterInfo& other) {
#ifdef REFUSED
  other = info;
#else
  other = std::move(info);
#endif
}
