// Compute pipelines from hal::ShaderInfo: descriptor set layouts from the reflection.
#include <map>
#include <string>

#include "check.hpp"
#include "device.hpp"
#include "pipeline_stats.hpp"

namespace hal::vulkan {

VkDescriptorType descriptor_type(BindingKind kind) {
  switch (kind) {
    // Dynamic: every dispatch points it at its own slice of the upload ring.
    case BindingKind::UniformBuffer:
      return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC;
    case BindingKind::StorageBuffer:
      return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case BindingKind::SampledImage:
      return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case BindingKind::StorageImage:
      return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case BindingKind::AccelerationStructure:
      return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  }
  return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

PipelineHandle VulkanDevice::create_pipeline(const ComputePipelineDesc& desc) {
  check_alive();
  const ShaderInfo& shader = *desc.shader;
  if (shader.spirv.empty())
    throw Error(ErrorKind::InvalidDescriptor, desc.name, "shader '" + std::string(shader.name) + "' has no SPIR-V");

  PipelineObject object;
  object.name = desc.name;
  object.shader = desc.shader;
  VkDevice device = device_;
  auto cleanup = [&] {
    if (object.pipeline) vkDestroyPipeline(device, object.pipeline, nullptr);
    if (object.layout) vkDestroyPipelineLayout(device, object.layout, nullptr);
    for (auto l : object.set_layouts) vkDestroyDescriptorSetLayout(device, l, nullptr);
  };
  VkShaderModule module = VK_NULL_HANDLE;
  try {
    std::map<std::uint32_t, std::vector<VkDescriptorSetLayoutBinding>> sets;
    std::uint32_t max_set = 0;
    for (const auto& b : shader.bindings) {
      if (b.kind == BindingKind::UniformBuffer) {
        if (object.uniform)
          throw Error(ErrorKind::InvalidDescriptor, desc.name,
                      "shader '" + std::string(shader.name) + "' has more than one uniform block");
        object.uniform = &b;
      }
      sets[b.set].push_back({b.binding, descriptor_type(b.kind), 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
      max_set = std::max(max_set, b.set);
    }
    if (object.uniform && shader.uniform_block_size == 0)
      throw Error(ErrorKind::InvalidDescriptor, desc.name,
                  "shader '" + std::string(shader.name) + "' has a uniform block of size 0");
    const std::uint32_t set_count = shader.bindings.empty() ? 0 : max_set + 1;
    for (std::uint32_t s = 0; s < set_count; ++s) {
      const auto& bindings = sets[s];
      VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
      info.bindingCount = static_cast<std::uint32_t>(bindings.size());
      info.pBindings = bindings.data();
      VkDescriptorSetLayout layout = VK_NULL_HANDLE;
      check_result(vkCreateDescriptorSetLayout(device_, &info, nullptr, &layout), "vkCreateDescriptorSetLayout",
                   desc.name);
      object.set_layouts.push_back(layout);
    }
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = static_cast<std::uint32_t>(object.set_layouts.size());
    layout_info.pSetLayouts = object.set_layouts.data();
    check_result(vkCreatePipelineLayout(device_, &layout_info, nullptr, &object.layout), "vkCreatePipelineLayout",
                 desc.name);

    VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    module_info.codeSize = shader.spirv.size_bytes();
    module_info.pCode = shader.spirv.data();
    check_result(vkCreateShaderModule(device_, &module_info, nullptr, &module), "vkCreateShaderModule", desc.name);

    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.layout = object.layout;
    if (pipeline_stats_)
      info.flags |=
          VK_PIPELINE_CREATE_CAPTURE_STATISTICS_BIT_KHR | VK_PIPELINE_CREATE_CAPTURE_INTERNAL_REPRESENTATIONS_BIT_KHR;
    check_result(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &object.pipeline),
                 "vkCreateComputePipelines", desc.name);
    vkDestroyShaderModule(device_, module, nullptr);
  } catch (...) {
    if (module) vkDestroyShaderModule(device_, module, nullptr);
    cleanup();
    throw;
  }
  set_name(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<std::uint64_t>(object.pipeline), desc.name);
  if (pipeline_stats_) dump_pipeline_stats(device_, object.pipeline, shader.name);
  return PipelineHandle{pipelines.add(std::move(object))};
}

}  // namespace hal::vulkan
