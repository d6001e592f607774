// The bitmask operators' helpers are not API: HasZeroOrOneBits takes a flag enum, not
// an operator's result.
#include <webgpu/webgpu_cpp.h>

bool single(wgpu::BufferUsage usage) {
#ifdef REFUSED
  return wgpu::HasZeroOrOneBits(usage | wgpu::BufferUsage::CopyDst);
#else
  return wgpu::HasZeroOrOneBits(usage);
#endif
}
