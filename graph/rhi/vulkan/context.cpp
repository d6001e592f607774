#include "graph/rhi/vulkan/context.h"

#include <cstring>
#include <utility>

namespace volgraph::vulkan {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string result_name(VkResult r) {
  switch (r) {
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    default: return "VkResult " + std::to_string(int(r));
  }
}

bool has_layer(const char* name) {
  uint32_t n = 0;
  vkEnumerateInstanceLayerProperties(&n, nullptr);
  std::vector<VkLayerProperties> layers(n);
  vkEnumerateInstanceLayerProperties(&n, layers.data());
  for (const auto& l : layers) {
    if (std::strcmp(l.layerName, name) == 0) return true;
  }
  return false;
}

bool has_instance_extension(const char* name) {
  uint32_t n = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  vkEnumerateInstanceExtensionProperties(nullptr, &n, exts.data());
  for (const auto& e : exts) {
    if (std::strcmp(e.extensionName, name) == 0) return true;
  }
  return false;
}

DeviceInfo describe(VkPhysicalDevice d) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(d, &props);
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(d, &features);
  return {props.properties.deviceName, std::string(driver.driverName) + " " + driver.driverInfo,
          props.properties.apiVersion, props.properties.vendorID, features.dualSrcBlend == VK_TRUE};
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
  uint32_t n = 0;
  vkEnumeratePhysicalDevices(instance, &n, nullptr);
  std::vector<VkPhysicalDevice> devices(n);
  vkEnumeratePhysicalDevices(instance, &n, devices.data());
  return devices;
}

VkInstance bare_instance() {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "volgraph";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance");
  return instance;
}

}  // namespace

void check(VkResult result, const char* what) {
  if (result == VK_SUCCESS) return;
  const std::string message = std::string(what) + " failed: " + result_name(result);
  switch (result) {
    case VK_ERROR_OUT_OF_HOST_MEMORY:
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
      throw DeviceError(DeviceError::Kind::out_of_memory, message);
    case VK_ERROR_DEVICE_LOST:
      throw DeviceError(DeviceError::Kind::device_lost, message);
    case VK_ERROR_INCOMPATIBLE_DRIVER:
      throw DeviceError(DeviceError::Kind::no_device, message + " (no Vulkan 1.3 driver; Debian: mesa-vulkan-drivers from bookworm-backports)");
    default:
      throw DeviceError(DeviceError::Kind::other, message);
  }
}

std::vector<DeviceInfo> Context::list_devices() {
  const VkInstance instance = bare_instance();
  std::vector<DeviceInfo> out;
  for (VkPhysicalDevice d : physical_devices(instance)) out.push_back(describe(d));
  vkDestroyInstance(instance, nullptr);
  return out;
}

std::unique_ptr<Context> Context::create(const ContextOptions& options) {
  std::unique_ptr<Context> c(new Context());
  c->simulate_ = options.simulate;
  c->create_instance(options.validation, options.instance_extensions);
  c->pick_device(options.device_index);
  c->create_device(options.device_extensions);
  return c;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user) {
  if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
  auto* self = static_cast<Context*>(user);
  std::lock_guard lock(self->messages_mutex_);
  self->messages_.push_back(std::string(data->pMessageIdName ? data->pMessageIdName : "") + ": " +
                            (data->pMessage ? data->pMessage : ""));
  return VK_FALSE;
}

void Context::create_instance(bool validation, const std::vector<const char*>& extra_extensions) {
  if (validation && !has_layer(kValidationLayer)) {
    throw DeviceError(DeviceError::Kind::unsupported,
                      "validation requested, but VK_LAYER_KHRONOS_validation is not installed (Debian: vulkan-validationlayers)");
  }
  const bool debug_utils = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (validation && !debug_utils) {
    throw DeviceError(DeviceError::Kind::unsupported, "validation needs VK_EXT_debug_utils, which the loader lacks");
  }
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "volgraph";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers, extensions;
  if (validation) layers.push_back(kValidationLayer);
  if (debug_utils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  extensions.insert(extensions.end(), extra_extensions.begin(), extra_extensions.end());

  // Synchronization validation, and the messenger for messages during vkCreateInstance.
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &Context::on_message;
  messenger.pUserData = this;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &messenger};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = validation ? static_cast<const void*>(&features) : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance");
  if (!validation) return;
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
  check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
}

void Context::pick_device(int index) {
  const std::vector<VkPhysicalDevice> devices = physical_devices(instance_);
  std::vector<VkPhysicalDevice> usable;
  for (VkPhysicalDevice d : devices) {
    if (describe(d).api_version >= VK_API_VERSION_1_3) usable.push_back(d);
  }
  if (usable.empty()) {
    throw DeviceError(DeviceError::Kind::no_device,
                      "no Vulkan 1.3 device (" + std::to_string(devices.size()) +
                          " older ones); install Mesa 25's lavapipe: apt-get install -t bookworm-backports mesa-vulkan-drivers");
  }
  if (index >= 0) {
    if (size_t(index) >= usable.size()) {
      std::string names;
      for (size_t i = 0; i < usable.size(); ++i) names += "\n  " + std::to_string(i) + ": " + describe(usable[i]).name;
      throw DeviceError(DeviceError::Kind::no_device,
                        "--device " + std::to_string(index) + ": there are " + std::to_string(usable.size()) +
                            " Vulkan 1.3 devices:" + names);
    }
    physical_ = usable[size_t(index)];
  } else {
    physical_ = usable.front();
    for (VkPhysicalDevice d : usable) {
      if (describe(d).name.find("llvmpipe") != std::string::npos) physical_ = d;
    }
  }
  info_ = describe(physical_);
  VkPhysicalDeviceVulkan11Properties props11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &props11};
  vkGetPhysicalDeviceProperties2(physical_, &props);
  limits_ = props.properties.limits;
  max_allocation_size_ = props11.maxMemoryAllocationSize;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
}

void Context::create_device(const std::vector<const char*>& extra_extensions) {
  VkPhysicalDeviceVulkan13Features have13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 have{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &have13};
  vkGetPhysicalDeviceFeatures2(physical_, &have);
  if (!have13.synchronization2 || !have13.dynamicRendering) {
    throw DeviceError(DeviceError::Kind::unsupported, info_.name + " lacks synchronization2 or dynamic rendering");
  }

  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &n, families.data());
  const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  bool found = false;
  for (uint32_t i = 0; i < n && !found; ++i) {
    if ((families[i].queueFlags & wanted) == wanted && families[i].timestampValidBits > 0) {
      queue_family_ = i;
      found = true;
    }
  }
  if (!found) throw DeviceError(DeviceError::Kind::unsupported, info_.name + " has no graphics+compute queue with timestamps");

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = queue_family_;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkPhysicalDeviceVulkan13Features want13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  want13.synchronization2 = VK_TRUE;
  want13.dynamicRendering = VK_TRUE;
  VkPhysicalDeviceVulkan12Features want12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &want13};
  want12.hostQueryReset = VK_TRUE;
  VkPhysicalDeviceFeatures want{};
  want.dualSrcBlend = info_.dual_source_blending ? VK_TRUE : VK_FALSE;  // one draw per translucent layer
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &want12};
  info.pEnabledFeatures = &want;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = uint32_t(extra_extensions.size());
  info.ppEnabledExtensionNames = extra_extensions.data();
  check(vkCreateDevice(physical_, &info, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  set_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(vkGetDeviceProcAddr(device_, "vkSetDebugUtilsObjectNameEXT"));
  begin_label_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(vkGetDeviceProcAddr(device_, "vkCmdBeginDebugUtilsLabelEXT"));
  end_label_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(vkGetDeviceProcAddr(device_, "vkCmdEndDebugUtilsLabelEXT"));
  if (!begin_label_ || !end_label_) begin_label_ = nullptr;

  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = queue_family_;
  check(vkCreateCommandPool(device_, &pool, nullptr, &pool_), "vkCreateCommandPool");
}

Context::~Context() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

void Context::set_name(VkObjectType type, uint64_t handle, const std::string& name) const {
  if (!set_name_ || name.empty()) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  set_name_(device_, &info);
}

std::vector<std::string> Context::take_validation_messages() {
  std::lock_guard lock(messages_mutex_);
  return std::exchange(messages_, {});
}

void Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

  const VkResult result = submit_recorded(cmd);
  vkFreeCommandBuffers(device_, pool_, 1, &cmd);
  check(result, "vkQueueSubmit2");
}

VkResult Context::submit_recorded(VkCommandBuffer cmd) {
  if (simulate_ == SimulatedFault::device_lost) return VK_ERROR_DEVICE_LOST;
  VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence = VK_NULL_HANDLE;
  check(vkCreateFence(device_, &fence_info, nullptr, &fence), "vkCreateFence");
  VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd_info.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd_info;
  const VkResult submitted = vkQueueSubmit2(queue_, 1, &submit, fence);
  const VkResult waited = submitted == VK_SUCCESS ? vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX) : submitted;
  vkDestroyFence(device_, fence, nullptr);
  return waited;
}

VkDeviceMemory Context::allocate_memory(uint64_t size, uint32_t memory_type, const std::string& label) {
  const uint64_t heap = memory_.memoryHeaps[memory_.memoryTypes[memory_type].heapIndex].size;
  const uint64_t limit = std::min(heap, max_allocation_size_ ? max_allocation_size_ : heap);
  if (size > limit) {
    throw DeviceError(DeviceError::Kind::out_of_memory,
                      label + " needs " + std::to_string(size >> 20) + " MiB in one allocation; " + info_.name +
                          " allows at most " + std::to_string(limit >> 20) + " MiB (" +
                          (limit == heap ? "its memory heap" : "maxMemoryAllocationSize") + ")");
  }
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = size;
  info.memoryTypeIndex = memory_type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  const VkResult result = simulate_ == SimulatedFault::out_of_memory ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                                                    : vkAllocateMemory(device_, &info, nullptr, &memory);
  check(result, ("vkAllocateMemory for " + label).c_str());
  return memory;
}

uint32_t Context::memory_type(uint32_t type_bits, VkMemoryPropertyFlags required) const {
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required) return i;
  }
  throw DeviceError(DeviceError::Kind::unsupported, "no memory type with the required properties");
}

}  // namespace volgraph::vulkan
