// dawn_device.cpp — instance → adapter → device through the C API, for the WebGPU tests.
#include "dawn_device.h"

#include <cstdint>

namespace volgraph::webgpu_test {

std::string to_string(WGPUStringView s) {
  if (s.data == nullptr) return {};
  return s.length == WGPU_STRLEN ? std::string(s.data) : std::string(s.data, s.length);
}

namespace {

struct AdapterResult {
  WGPUAdapter adapter = nullptr;
  std::string message;
};

struct DeviceResult {
  WGPUDevice device = nullptr;
  std::string message;
};

void on_adapter(WGPURequestAdapterStatus status, WGPUAdapter adapter, WGPUStringView message, void* result,
                void*) {
  auto* r = static_cast<AdapterResult*>(result);
  r->message = "status " + std::to_string(status) + ": " + to_string(message);
  if (status == WGPURequestAdapterStatus_Success) r->adapter = adapter;
}

void on_device(WGPURequestDeviceStatus status, WGPUDevice device, WGPUStringView message, void* result, void*) {
  auto* r = static_cast<DeviceResult*>(result);
  r->message = "status " + std::to_string(status) + ": " + to_string(message);
  if (status == WGPURequestDeviceStatus_Success) r->device = device;
}

void on_uncaptured_error(WGPUDevice const*, WGPUErrorType type, WGPUStringView message, void* events, void*) {
  static_cast<DeviceEvents*>(events)->uncaptured_errors.push_back("type " + std::to_string(type) + ": " +
                                                                   to_string(message));
}

void on_device_lost(WGPUDevice const*, WGPUDeviceLostReason reason, WGPUStringView message, void* events, void*) {
  static_cast<DeviceEvents*>(events)->lost.push_back("reason " + std::to_string(reason) + ": " + to_string(message));
}

}  // namespace

DawnDevice::DawnDevice() {
  WGPUInstanceDescriptor descriptor = {};
  descriptor.capabilities.timedWaitAnyEnable = 1;  // WaitAny with a timeout
  instance = wgpuCreateInstance(&descriptor);
  if (instance == nullptr) {
    failure = "wgpuCreateInstance returned null";
    return;
  }
  request_adapter();
  if (adapter != nullptr) request_device();
}

DawnDevice::~DawnDevice() {
  if (device != nullptr) {
    wgpuDeviceDestroy(device);
    wgpuDeviceRelease(device);
  }
  if (adapter != nullptr) wgpuAdapterRelease(adapter);
  if (instance != nullptr) {
    wgpuInstanceProcessEvents(instance);  // delivers the device-lost callback of Destroy
    wgpuInstanceRelease(instance);
  }
}

bool DawnDevice::wait(WGPUFuture future) const {
  WGPUFutureWaitInfo info = {future, 0};
  return wgpuInstanceWaitAny(instance, 1, &info, UINT64_MAX) == WGPUWaitStatus_Success && info.completed;
}

void DawnDevice::request_adapter() {
  AdapterResult result;
  WGPURequestAdapterCallbackInfo callback = {};
  callback.mode = WGPUCallbackMode_WaitAnyOnly;
  callback.callback = on_adapter;
  callback.userdata1 = &result;
  if (!wait(wgpuInstanceRequestAdapter(instance, nullptr, callback)) || result.adapter == nullptr) {
    failure = "no adapter (" + result.message + ")";
    return;
  }
  adapter = result.adapter;
}

void DawnDevice::request_device() {
  DeviceResult result;
  WGPUDeviceDescriptor descriptor = {};
  descriptor.deviceLostCallbackInfo.mode = WGPUCallbackMode_AllowProcessEvents;
  descriptor.deviceLostCallbackInfo.callback = on_device_lost;
  descriptor.deviceLostCallbackInfo.userdata1 = &events;
  descriptor.uncapturedErrorCallbackInfo.callback = on_uncaptured_error;
  descriptor.uncapturedErrorCallbackInfo.userdata1 = &events;
  WGPURequestDeviceCallbackInfo callback = {};
  callback.mode = WGPUCallbackMode_WaitAnyOnly;
  callback.callback = on_device;
  callback.userdata1 = &result;
  if (!wait(wgpuAdapterRequestDevice(adapter, &descriptor, callback)) || result.device == nullptr) {
    failure = "no device (" + result.message + ")";
    return;
  }
  device = result.device;
}

}  // namespace volgraph::webgpu_test
