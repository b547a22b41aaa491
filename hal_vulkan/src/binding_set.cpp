// Binding sets: named C++ resources written into descriptor sets. The uniform block is bound
// implicitly to the device's upload ring.
#include <string>

#include "check.hpp"
#include "device.hpp"

namespace hal::vulkan {

VkDescriptorType descriptor_type(BindingKind kind);

BindingSetHandle VulkanDevice::create_binding_set(const BindingSetDesc& desc) {
  check_alive();
  const PipelineObject& pipeline = pipelines.get(desc.pipeline.id, "pipeline");
  const ShaderInfo& shader = *pipeline.shader;

  // Entries by binding index (hal::validate checked names, kinds, usages and formats).
  BindingSetObject object;
  object.name = desc.name;
  object.pipeline = desc.pipeline;
  object.shader = pipeline.shader;
  object.bound.resize(shader.bindings.size());
  for (const auto& entry : desc.entries)
    if (const ShaderBinding* b = shader.find(entry.name))
      object.bound[static_cast<std::size_t>(b - shader.bindings.data())] = entry.resource;

  // A pool sized for exactly this set, so binding sets never compete for descriptors.
  std::vector<VkDescriptorPoolSize> sizes;
  for (const auto& b : shader.bindings) {
    const VkDescriptorType type = descriptor_type(b.kind);
    bool found = false;
    for (auto& s : sizes)
      if (s.type == type) {
        ++s.descriptorCount;
        found = true;
      }
    if (!found) sizes.push_back({type, 1});
  }
  const auto set_count = static_cast<std::uint32_t>(pipeline.set_layouts.size());
  if (set_count > 0) {
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = set_count;
    pool_info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    pool_info.pPoolSizes = sizes.data();
    check_result(vkCreateDescriptorPool(device_, &pool_info, nullptr, &object.pool), "vkCreateDescriptorPool", desc.name);
    object.sets.resize(set_count);
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = object.pool;
    alloc.descriptorSetCount = set_count;
    alloc.pSetLayouts = pipeline.set_layouts.data();
    const VkResult result = vkAllocateDescriptorSets(device_, &alloc, object.sets.data());
    if (result != VK_SUCCESS) vkDestroyDescriptorPool(device_, object.pool, nullptr);
    check_result(result, "vkAllocateDescriptorSets", desc.name);
    set_name(VK_OBJECT_TYPE_DESCRIPTOR_POOL, reinterpret_cast<std::uint64_t>(object.pool), desc.name);
  }

  // Descriptor writes; the info structs must outlive vkUpdateDescriptorSets.
  std::vector<VkWriteDescriptorSet> writes;
  std::vector<VkDescriptorBufferInfo> buffer_infos;
  std::vector<VkDescriptorImageInfo> image_infos;
  std::vector<VkWriteDescriptorSetAccelerationStructureKHR> accel_infos;
  std::vector<VkAccelerationStructureKHR> accel_handles;
  buffer_infos.reserve(shader.bindings.size());
  image_infos.reserve(shader.bindings.size());
  accel_infos.reserve(shader.bindings.size());
  accel_handles.reserve(shader.bindings.size());
  for (std::size_t i = 0; i < shader.bindings.size(); ++i) {
    const ShaderBinding& b = shader.bindings[i];
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = object.sets[b.set];
    write.dstBinding = b.binding;
    write.descriptorCount = 1;
    write.descriptorType = descriptor_type(b.kind);
    if (b.kind == BindingKind::UniformBuffer) {
      buffer_infos.push_back({ring_.buffer, 0, shader.uniform_block_size});
      write.pBufferInfo = &buffer_infos.back();
    } else if (object.bound[i].id == 0) {
      continue;  // reported when a dispatch uses the set
    } else if (b.kind == BindingKind::StorageBuffer) {
      buffer_infos.push_back({buffers.get(object.bound[i].id, "buffer").buffer, 0, VK_WHOLE_SIZE});
      write.pBufferInfo = &buffer_infos.back();
    } else if (b.kind == BindingKind::AccelerationStructure) {
      accel_handles.push_back(accels.get(object.bound[i].id, "acceleration structure").handle);
      VkWriteDescriptorSetAccelerationStructureKHR info{
          VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
      info.accelerationStructureCount = 1;
      info.pAccelerationStructures = &accel_handles.back();
      accel_infos.push_back(info);
      write.pNext = &accel_infos.back();
    } else {
      image_infos.push_back({VK_NULL_HANDLE, images.get(object.bound[i].id, "image").view, VK_IMAGE_LAYOUT_GENERAL});
      write.pImageInfo = &image_infos.back();
    }
    writes.push_back(write);
  }
  if (!writes.empty())
    vkUpdateDescriptorSets(device_, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  return BindingSetHandle{binding_sets.add(std::move(object))};
}

}  // namespace hal::vulkan
