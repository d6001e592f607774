// shaders/composite.comp on lavapipe against its CPU twin (passes/shading/tonemap.h):
// every variant and several exposures, on a frame that is not a multiple of the
// workgroup size, with radiances from 0 to 1e4 (and a negative one, clamped to 0).
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "tests/gpu/validation_messages.h"

#include "graph/rhi/vulkan/context.h"
#include "passes/shading/tonemap.h"
#include "shaders/shader_library.h"

namespace volgraph::vulkan {
namespace {

constexpr uint32_t kWidth = 13, kHeight = 11;

// Just enough Vulkan to run one compute shader on one sampled and one storage image.
class ComputeRun {
 public:
  explicit ComputeRun(Context& c) : c_(c) {}
  ~ComputeRun() {
    const VkDevice d = c_.device();
    for (VkImageView v : views_) vkDestroyImageView(d, v, nullptr);
    for (VkImage i : images_) vkDestroyImage(d, i, nullptr);
    for (VkBuffer b : buffers_) vkDestroyBuffer(d, b, nullptr);
    for (VkDeviceMemory m : memory_) vkFreeMemory(d, m, nullptr);
    if (pipeline_) vkDestroyPipeline(d, pipeline_, nullptr);
    if (pipeline_layout_) vkDestroyPipelineLayout(d, pipeline_layout_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
    if (pool_) vkDestroyDescriptorPool(d, pool_, nullptr);
    if (sampler_) vkDestroySampler(d, sampler_, nullptr);
    if (module_) vkDestroyShaderModule(d, module_, nullptr);
  }

  VkBuffer host_buffer(VkDeviceSize size, VkBufferUsageFlags usage, void** mapped) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    VkBuffer b;
    check(vkCreateBuffer(c_.device(), &info, nullptr, &b), "vkCreateBuffer");
    buffers_.push_back(b);
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(c_.device(), b, &req);
    const VkDeviceMemory m = allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkBindBufferMemory(c_.device(), b, m, 0), "vkBindBufferMemory");
    check(vkMapMemory(c_.device(), m, 0, VK_WHOLE_SIZE, 0, mapped), "vkMapMemory");
    return b;
  }

  std::pair<VkImage, VkImageView> image(VkImageUsageFlags usage) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    info.extent = {kWidth, kHeight, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    VkImage i;
    check(vkCreateImage(c_.device(), &info, nullptr, &i), "vkCreateImage");
    images_.push_back(i);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(c_.device(), i, &req);
    check(vkBindImageMemory(c_.device(), i, allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT), 0), "vkBindImageMemory");
    VkImageViewCreateInfo v{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    v.image = i;
    v.viewType = VK_IMAGE_VIEW_TYPE_2D;
    v.format = info.format;
    v.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view;
    check(vkCreateImageView(c_.device(), &v, nullptr, &view), "vkCreateImageView");
    views_.push_back(view);
    return {i, view};
  }

  // Layout: 0 sampled texture, 1 sampler, 2 storage image, 3 uniform buffer.
  VkDescriptorSet pipeline(std::span<const uint32_t> spirv) {
    const VkDevice d = c_.device();
    VkShaderModuleCreateInfo m{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    m.codeSize = spirv.size_bytes();
    m.pCode = spirv.data();
    check(vkCreateShaderModule(d, &m, nullptr, &module_), "vkCreateShaderModule");
    const VkDescriptorType types[] = {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLER,
                                      VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
    VkDescriptorSetLayoutBinding bindings[4];
    VkDescriptorPoolSize sizes[4];
    for (uint32_t i = 0; i < 4; ++i) {
      bindings[i] = {i, types[i], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
      sizes[i] = {types[i], 1};
    }
    VkDescriptorSetLayoutCreateInfo l{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    l.bindingCount = 4;
    l.pBindings = bindings;
    check(vkCreateDescriptorSetLayout(d, &l, nullptr, &set_layout_), "vkCreateDescriptorSetLayout");
    VkPipelineLayoutCreateInfo pl{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &set_layout_;
    check(vkCreatePipelineLayout(d, &pl, nullptr, &pipeline_layout_), "vkCreatePipelineLayout");
    VkComputePipelineCreateInfo cp{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cp.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_COMPUTE_BIT, module_, "main", nullptr};
    cp.layout = pipeline_layout_;
    check(vkCreateComputePipelines(d, VK_NULL_HANDLE, 1, &cp, nullptr, &pipeline_), "vkCreateComputePipelines");
    VkDescriptorPoolCreateInfo p{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    p.maxSets = 1;
    p.poolSizeCount = 4;
    p.pPoolSizes = sizes;
    check(vkCreateDescriptorPool(d, &p, nullptr, &pool_), "vkCreateDescriptorPool");
    VkDescriptorSetAllocateInfo a{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    a.descriptorPool = pool_;
    a.descriptorSetCount = 1;
    a.pSetLayouts = &set_layout_;
    VkDescriptorSet set;
    check(vkAllocateDescriptorSets(d, &a, &set), "vkAllocateDescriptorSets");
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    check(vkCreateSampler(d, &s, nullptr, &sampler_), "vkCreateSampler");
    return set;
  }

  VkSampler sampler() const { return sampler_; }
  VkPipeline compute_pipeline() const { return pipeline_; }
  VkPipelineLayout layout() const { return pipeline_layout_; }

 private:
  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags props) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = c_.memory_type(req.memoryTypeBits, props);
    VkDeviceMemory m;
    check(vkAllocateMemory(c_.device(), &info, nullptr, &m), "vkAllocateMemory");
    memory_.push_back(m);
    return m;
  }

  Context& c_;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkBuffer> buffers_;
  std::vector<VkDeviceMemory> memory_;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

void image_barrier(VkCommandBuffer cmd, VkImage image, VkPipelineStageFlags2 src, VkAccessFlags2 src_access,
                   VkPipelineStageFlags2 dst, VkAccessFlags2 dst_access, VkImageLayout from, VkImageLayout to) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = src;
  b.srcAccessMask = src_access;
  b.dstStageMask = dst;
  b.dstAccessMask = dst_access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

float radiance_at(uint32_t x, uint32_t y, uint32_t c) {
  const float v = std::pow(10.0f, -3.0f + 7.0f * float(x + kWidth * y) / float(kWidth * kHeight)) * (1.0f + 0.3f * float(c));
  return (x == 3 && y == 2) ? -1.0f : v;  // one negative radiance: clamped to 0
}

TEST(CompositeShader, MatchesTheCpuTwinForEveryToneMap) {
  const std::span<const uint32_t> spirv = shader_spirv("composite.comp");
  ASSERT_FALSE(spirv.empty());
  auto c = Context::create({.validation = true});
  for (const shading::ToneMap op : {shading::ToneMap::none, shading::ToneMap::aces, shading::ToneMap::reinhard}) {
    for (const float exposure : {-2.0f, 0.0f, 1.5f}) {
      ComputeRun run(*c);
      const VkDeviceSize bytes = VkDeviceSize(kWidth) * kHeight * 16;
      void *upload_ptr, *readback_ptr, *params_ptr;
      const VkBuffer upload = run.host_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, &upload_ptr);
      const VkBuffer readback = run.host_buffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, &readback_ptr);
      const VkBuffer params = run.host_buffer(16, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &params_ptr);
      auto* texels = static_cast<float*>(upload_ptr);
      for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x)
          for (uint32_t ch = 0; ch < 4; ++ch) texels[4 * (x + kWidth * y) + ch] = ch == 3 ? 1.0f : radiance_at(x, y, ch);
      const uint32_t size[2] = {kWidth, kHeight};
      const int op_value = int(op);
      std::memcpy(params_ptr, size, 8);
      std::memcpy(static_cast<char*>(params_ptr) + 8, &exposure, 4);
      std::memcpy(static_cast<char*>(params_ptr) + 12, &op_value, 4);

      const auto input_image = run.image(VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT);
      const auto output_image = run.image(VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
      const VkImage input = input_image.first, output = output_image.first;
      const VkImageView input_view = input_image.second, output_view = output_image.second;
      const VkDescriptorSet set = run.pipeline(spirv);
      VkDescriptorImageInfo sampled{VK_NULL_HANDLE, input_view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
      VkDescriptorImageInfo sampler{run.sampler(), VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED};
      VkDescriptorImageInfo storage{VK_NULL_HANDLE, output_view, VK_IMAGE_LAYOUT_GENERAL};
      VkDescriptorBufferInfo uniform{params, 0, 16};
      VkWriteDescriptorSet writes[4];
      const VkDescriptorType types[] = {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLER,
                                        VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
      const VkDescriptorImageInfo* infos[] = {&sampled, &sampler, &storage, nullptr};
      for (uint32_t i = 0; i < 4; ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, set, i, 0, 1, types[i], infos[i],
                     i == 3 ? &uniform : nullptr, nullptr};
      }
      vkUpdateDescriptorSets(c->device(), 4, writes, 0, nullptr);

      c->submit_and_wait([&](VkCommandBuffer cmd) {
        image_barrier(cmd, input, VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                      VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy region{0, 0, 0, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {}, {kWidth, kHeight, 1}};
        vkCmdCopyBufferToImage(cmd, upload, input, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        image_barrier(cmd, input, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        image_barrier(cmd, output, VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, run.compute_pipeline());
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, run.layout(), 0, 1, &set, 0, nullptr);
        vkCmdDispatch(cmd, (kWidth + 7) / 8, (kHeight + 7) / 8, 1);
        image_barrier(cmd, output, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_GENERAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        vkCmdCopyImageToBuffer(cmd, output, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback, 1, &region);
      });

      const auto* result = static_cast<const float*>(readback_ptr);
      double worst = 0;
      for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
          const shading::Rgb in = {radiance_at(x, y, 0), radiance_at(x, y, 1), radiance_at(x, y, 2)};
          const shading::Rgb want = shading::tone_map(in, exposure, op);
          for (uint32_t ch = 0; ch < 3; ++ch) {
            const double got = result[4 * (x + kWidth * y) + ch];
            // float32 evaluation of the same formula: relative error well under 1e-5.
            worst = std::max(worst, std::abs(got - want[ch]) / std::max(1e-3, std::abs(want[ch])));
          }
          EXPECT_EQ(result[4 * (x + kWidth * y) + 3], 1.0f);
        }
      }
      EXPECT_LT(worst, 1e-5) << "tone map " << int(op) << " exposure " << exposure;
    }
  }
  const auto messages = c->take_validation_messages();
  EXPECT_TRUE(messages.empty()) << joined(messages);
}

}  // namespace
}  // namespace volgraph::vulkan
