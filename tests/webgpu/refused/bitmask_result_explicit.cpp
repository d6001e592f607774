// A bitmask operator's result (BoolConvertible) comes only from the operators; it tests
// as a bool and converts back to the flag enum. The operators' helpers are not API.
#include <webgpu/webgpu_cpp.h>

bool readable(wgpu::BufferUsage usage) {
#ifdef REFUSED
  wgpu::BoolConvertible<wgpu::BufferUsage> none = 0;
  return none;
#else
  const wgpu::BufferUsage both = wgpu::BufferUsage::MapRead | wgpu::BufferUsage::CopyDst;
  return (usage & both) && wgpu::HasZeroOrOneBits(wgpu::BufferUsage::MapRead);
#endif
}
