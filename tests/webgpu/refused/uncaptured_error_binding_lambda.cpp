// The uncaptured-error callback may run any number of times with no last call to free
// a callable after, so both headers take only a function (or captureless lambda),
// with state through the userdata overload; a capturing lambda is a static_assert.
#include <webgpu/webgpu_cpp.h>

void set_callbacks(wgpu::DeviceDescriptor& descriptor, int* errors) {
#ifdef REFUSED
  descriptor.SetUncapturedErrorCallback([errors](const wgpu::Device&, wgpu::ErrorType, wgpu::StringView) { ++*errors; });
#else
  descriptor.SetUncapturedErrorCallback(
      [](const wgpu::Device&, wgpu::ErrorType, wgpu::StringView, int* count) { ++*count; }, errors);
#endif
}
