// create_webgpu_device when the build found no Dawn library (webgpu_backend.h).
#include "tools/webgpu_backend.h"

namespace volgraph {

std::unique_ptr<rhi::Device> create_webgpu_device(SimulatedFault) {
  throw DeviceError(DeviceError::Kind::unsupported,
                    "this volgraph was built without Dawn (tools/fetch_dawn.sh fetches it; then reconfigure), so "
                    "--backend webgpu is unavailable");
}

std::string describe_webgpu_adapter() { return "webgpu: unavailable (this volgraph was built without Dawn)"; }

}  // namespace volgraph
