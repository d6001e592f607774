// SupportedFeatures' list belongs to the implementation: read-only to callers.
#include <webgpu/webgpu_cpp.h>

size_t count(wgpu::SupportedFeatures& features) {
#ifdef REFUSED
  features.featureCount = 0;
#endif
  return features.featureCount;
}
