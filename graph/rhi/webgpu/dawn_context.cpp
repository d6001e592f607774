// Dawn instance → adapter → device (dawn_context.h), and the device's error and loss
// callbacks turned into volgraph's messages and DeviceErrors.
#include "graph/rhi/webgpu/dawn_context.h"

#include <cstdint>
#include <optional>

#include "graph/rhi/webgpu/adapter_choice.h"

namespace volgraph::webgpu {
namespace {

std::string text_of(wgpu::StringView s) {
  if (s.data == nullptr) return {};
  return s.length == WGPU_STRLEN ? std::string(s.data) : std::string(s.data, s.length);
}

std::string_view error_type_name(wgpu::ErrorType type) {
  switch (type) {
    case wgpu::ErrorType::Validation: return "validation error";
    case wgpu::ErrorType::OutOfMemory: return "out of memory";
    case wgpu::ErrorType::Internal: return "internal error";
    default: return "error";
  }
}

// Dawn's message up to its first line break: the rest is Dawn's call context.
std::string first_line(const std::string& message) { return message.substr(0, message.find('\n')); }

// Whether a loss message names one of Vulkan's out-of-memory results (Vulkan 1.3 spec,
// VkResult): Dawn reports a failed memory bind by losing the device, with that name.
bool names_out_of_memory(std::string_view message) {
  return message.find("VK_ERROR_OUT_OF_DEVICE_MEMORY") != std::string_view::npos ||
         message.find("VK_ERROR_OUT_OF_HOST_MEMORY") != std::string_view::npos;
}

// Dawn rounds time stamps to 100 µs by default (a fingerprinting guard for browsers);
// volgraph measures passes, so it asks for them unrounded.
constexpr const char* kDisabledToggles[] = {"timestamp_quantization"};

}  // namespace

std::unique_ptr<DawnContext> DawnContext::create(const DawnOptions& options) {
  std::unique_ptr<DawnContext> context(new DawnContext(options));
  wgpu::InstanceDescriptor descriptor;
  descriptor.capabilities.timedWaitAnyEnable = true;
  context->instance_ = wgpu::CreateInstance(&descriptor);
  if (!context->instance_) throw DeviceError(DeviceError::Kind::no_device, "Dawn: wgpuCreateInstance failed");
  context->request_adapter();
  context->request_device();
  return context;
}

DawnContext::~DawnContext() {
  if (device_) device_.Destroy();
  if (instance_) instance_.ProcessEvents();  // delivers the loss Destroy causes
}

void DawnContext::wait(const wgpu::Future& future, std::string_view what) const {
  if (instance_.WaitAny(future, UINT64_MAX) != wgpu::WaitStatus::Success) {
    throw DeviceError(DeviceError::Kind::other, "Dawn: waiting for " + std::string(what) + " failed");
  }
}

void DawnContext::begin_allocation() const { device_.PushErrorScope(wgpu::ErrorFilter::OutOfMemory); }

void DawnContext::end_allocation(std::string_view what) {
  std::optional<std::string> out_of_memory;
  wait(device_.PopErrorScope(wgpu::CallbackMode::WaitAnyOnly,
                             [&out_of_memory](wgpu::PopErrorScopeStatus status, wgpu::ErrorType type, wgpu::StringView message) {
                               if (status == wgpu::PopErrorScopeStatus::Success && type == wgpu::ErrorType::OutOfMemory) {
                                 out_of_memory = text_of(message);
                               }
                             }),
       "an error scope");
  const std::string creating = "Dawn: creating " + std::string(what) + ": ";
  if (out_of_memory) throw DeviceError(DeviceError::Kind::out_of_memory, creating + first_line(*out_of_memory));
  const std::lock_guard lock(mutex_);
  if (lost_for_memory_) throw DeviceError(DeviceError::Kind::out_of_memory, creating + first_line(lost_));
}

void DawnContext::wait_for_queue() const {
  bool done = false;
  wait(queue_.OnSubmittedWorkDone(wgpu::CallbackMode::WaitAnyOnly,
                                  [&done](wgpu::QueueWorkDoneStatus status, wgpu::StringView) {
                                    done = status == wgpu::QueueWorkDoneStatus::Success;
                                  }),
       "the queue");
  if (!done && lost_.empty()) throw DeviceError(DeviceError::Kind::other, "Dawn: the queue's work did not complete");
}

void DawnContext::request_adapter() {
  std::string message;
  wait(instance_.RequestAdapter(nullptr, wgpu::CallbackMode::WaitAnyOnly,
                                [this, &message](wgpu::RequestAdapterStatus status, wgpu::Adapter adapter, wgpu::StringView text) {
                                  message = text_of(text);
                                  if (status == wgpu::RequestAdapterStatus::Success) adapter_ = std::move(adapter);
                                }),
       "an adapter");
  if (!adapter_) throw DeviceError(DeviceError::Kind::no_device, "Dawn offers no adapter: " + message);
  wgpu::AdapterInfo info;
  adapter_.GetInfo(&info);
  const std::optional<std::string> fallback = fallback_adapter_reason(info.backendType, info.adapterType, info.device);
  if (fallback && !options_.allow_fallback_adapter) {
    throw DeviceError(DeviceError::Kind::no_device,
                      "Dawn offers only " + *fallback +
                          "; install a Vulkan driver (lavapipe: mesa-vulkan-drivers) or check VK_ICD_FILENAMES, or "
                          "set VOLGRAPH_WEBGPU_ALLOW_FALLBACK=1 to render on it anyway");
  }
  info_ = {"webgpu", text_of(info.device), "Dawn on " + text_of(info.description)};
  timestamps_ = adapter_.HasFeature(wgpu::FeatureName::TimestampQuery);
  dual_source_blending_ = adapter_.HasFeature(wgpu::FeatureName::DualSourceBlending);
}

void DawnContext::request_device() {
  std::vector<wgpu::FeatureName> features;
  if (timestamps_) features.push_back(wgpu::FeatureName::TimestampQuery);
  // Additive blending into rgba32_float targets (accumulation), as on Vulkan.
  if (adapter_.HasFeature(wgpu::FeatureName::Float32Blendable)) features.push_back(wgpu::FeatureName::Float32Blendable);
  // A fragment's second blend source (BlendFactor::Src1): one draw per translucent layer.
  if (dual_source_blending_) features.push_back(wgpu::FeatureName::DualSourceBlending);
  wgpu::Limits limits;  // all the adapter allows (large shadow maps, 3D textures)
  adapter_.GetLimits(&limits);
  wgpu::DawnTogglesDescriptor toggles;
  toggles.disabledToggleCount = std::size(kDisabledToggles);
  toggles.disabledToggles = kDisabledToggles;
  wgpu::DeviceDescriptor descriptor;
  descriptor.nextInChain = &toggles;
  descriptor.requiredFeatureCount = features.size();
  descriptor.requiredFeatures = features.data();
  descriptor.requiredLimits = &limits;
  // Dawn takes the uncaptured-error callback only as a function with a userdata pointer
  // (it may be called any number of times, so it owns no callable); the loss callback
  // takes the same form, so both reach this context alike.
  descriptor.SetUncapturedErrorCallback(
      [](const wgpu::Device&, wgpu::ErrorType type, wgpu::StringView message, DawnContext* self) {
        self->on_error(type, text_of(message));
      },
      this);
  descriptor.SetDeviceLostCallback(
      wgpu::CallbackMode::AllowSpontaneous,
      [](const wgpu::Device&, wgpu::DeviceLostReason reason, wgpu::StringView message, DawnContext* self) {
        self->on_lost(reason, text_of(message));
      },
      this);
  std::string message;
  wait(adapter_.RequestDevice(&descriptor, wgpu::CallbackMode::WaitAnyOnly,
                              [this, &message](wgpu::RequestDeviceStatus status, wgpu::Device device, wgpu::StringView text) {
                                message = text_of(text);
                                if (status == wgpu::RequestDeviceStatus::Success) device_ = std::move(device);
                              }),
       "a device");
  if (!device_) throw DeviceError(DeviceError::Kind::no_device, "Dawn gives no device on " + info_.device + ": " + message);
  queue_ = device_.GetQueue();
}

void DawnContext::on_error(wgpu::ErrorType type, std::string_view message) {
  const std::lock_guard lock(mutex_);
  if (type == wgpu::ErrorType::OutOfMemory && reported_ == messages_.size()) out_of_memory_ = true;
  messages_.push_back("Dawn " + std::string(error_type_name(type)) + ": " + std::string(message));
}

void DawnContext::on_lost(wgpu::DeviceLostReason reason, std::string_view message) {
  if (reason == wgpu::DeviceLostReason::Destroyed || reason == wgpu::DeviceLostReason::CallbackCancelled) return;
  const std::lock_guard lock(mutex_);
  lost_ = std::string(message);
  lost_for_memory_ = names_out_of_memory(message);
}

void DawnContext::check() {
  const std::lock_guard lock(mutex_);
  if (lost_for_memory_) throw DeviceError(DeviceError::Kind::out_of_memory, "Dawn: " + first_line(lost_));
  if (!lost_.empty()) throw DeviceError(DeviceError::Kind::device_lost, "Dawn: " + lost_);
  if (!options_.errors_throw || reported_ == messages_.size()) return;
  const std::string first = messages_[reported_];
  const bool memory = out_of_memory_;
  reported_ = messages_.size();
  out_of_memory_ = false;
  throw DeviceError(memory ? DeviceError::Kind::out_of_memory : DeviceError::Kind::other, first);
}

std::vector<std::string> DawnContext::take_messages() {
  const std::lock_guard lock(mutex_);
  std::vector<std::string> out = std::move(messages_);
  messages_.clear();
  reported_ = 0;
  return out;
}

}  // namespace volgraph::webgpu
