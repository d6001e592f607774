// wgpu::StringView converts to std::string_view (and explicitly to any (data, length)
// type), not back to the C WGPUStringView.
#include <string>
#include <string_view>
#include <webgpu/webgpu_cpp.h>

std::string text(wgpu::StringView s) {
#ifdef REFUSED
  WGPUStringView c = s;
  return std::string(c.data, c.length);
#else
  return std::string(std::string_view(s)) + std::string(s);
#endif
}
