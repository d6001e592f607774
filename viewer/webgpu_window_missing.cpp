// make_webgpu_window where volgraph was built without Dawn (no libwebgpu_wrapper.so at
// configure time): the WebGPU viewer is refused as the user's setup.
#include "viewer/window_backend.h"

#include "graph/rhi/device_error.h"

namespace volgraph::viewer {

std::unique_ptr<WindowBackend> make_webgpu_window(GLFWwindow*, const ViewOptions&) {
  throw DeviceError(DeviceError::Kind::unsupported, "view --backend webgpu: this volgraph was built without Dawn (tools/fetch_dawn.sh)");
}

}  // namespace volgraph::viewer
