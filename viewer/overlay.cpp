#include "viewer/overlay.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include "graph/rhi/vulkan/context.h"
#include "viewer/presenter.h"

namespace volgraph::viewer {
namespace {

// The backend allocates one combined image sampler (the font atlas); a few spare.
VkDescriptorPool create_pool(VkDevice device) {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  info.maxSets = 4;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  vulkan::check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
  return pool;
}

void check_result(VkResult r) { vulkan::check(r, "Dear ImGui's Vulkan backend"); }

}  // namespace

Overlay::Overlay(GLFWwindow* window, bool vulkan) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written beside the user's files
  ImGui::StyleColorsDark();
  if (vulkan) {
    ImGui_ImplGlfw_InitForVulkan(window, true);
  } else {
    ImGui_ImplGlfw_InitForOther(window, true);
  }
}

Overlay::~Overlay() {
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void Overlay::begin_frame() {
  new_renderer_frame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void Overlay::end_frame() { ImGui::Render(); }

bool Overlay::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Overlay::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

VulkanOverlay::VulkanOverlay(vulkan::Context& context, GLFWwindow* window, Presenter& presenter) : Overlay(window, true), context_(context) {
  pool_ = create_pool(context.device());
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context.instance();
  info.PhysicalDevice = context.physical_device();
  info.Device = context.device();
  info.QueueFamily = context.queue_family();
  info.Queue = context.queue();
  info.DescriptorPool = pool_;
  info.MinImageCount = std::max(2u, presenter.image_count());
  info.ImageCount = std::max(2u, presenter.image_count());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = check_result;
  ImGui_ImplVulkan_Init(&info, presenter.render_pass());
  presenter.submit_now([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

VulkanOverlay::~VulkanOverlay() {
  vkDeviceWaitIdle(context_.device());
  ImGui_ImplVulkan_Shutdown();
  vkDestroyDescriptorPool(context_.device(), pool_, nullptr);
}

void VulkanOverlay::new_renderer_frame() { ImGui_ImplVulkan_NewFrame(); }

void VulkanOverlay::draw(VkCommandBuffer cmd) const { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); }

}  // namespace volgraph::viewer
