// Acceleration structures: BLAS from triangle or box buffers, TLAS from instances copied at record time,
// builds and in-place updates, each structure owning its scratch buffer.
#include <cstring>
#include <string>

#include "check.hpp"
#include "command_list.hpp"
#include "device.hpp"

namespace hal::vulkan {
namespace {

VkAccelerationStructureGeometryKHR triangles(VkDeviceAddress vertices, std::uint32_t vertex_count,
                                             VkDeviceAddress indices) {
  VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
  // Opaque: ray queries commit the closest triangle without any shader-side candidate handling.
  geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
  auto& t = geometry.geometry.triangles;
  t.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
  t.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
  t.vertexData.deviceAddress = vertices;
  t.vertexStride = 12;
  t.maxVertex = vertex_count - 1;
  t.indexType = VK_INDEX_TYPE_UINT32;
  t.indexData.deviceAddress = indices;
  return geometry;
}

VkAccelerationStructureGeometryKHR boxes(VkDeviceAddress data) {
  VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
  geometry.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;  // the shader decides every hit; no any-hit stage
  geometry.geometry.aabbs.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
  geometry.geometry.aabbs.data.deviceAddress = data;
  geometry.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
  return geometry;
}

VkAccelerationStructureGeometryKHR blas_geometry(const BlasDesc& desc, VkDeviceAddress vertices, VkDeviceAddress indices,
                                                 VkDeviceAddress box_data) {
  return desc.geometry == BlasGeometry::Boxes ? boxes(box_data) : triangles(vertices, desc.vertex_count, indices);
}

VkAccelerationStructureGeometryKHR instances(VkDeviceAddress data) {
  VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry.geometry.instances.arrayOfPointers = VK_FALSE;
  geometry.geometry.instances.data.deviceAddress = data;
  return geometry;
}

VkBuildAccelerationStructureFlagsKHR build_flags(bool allow_update) {
  return VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
         (allow_update ? VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_UPDATE_BIT_KHR : 0);
}

}  // namespace

namespace {

// Storage and scratch of a new structure, sized from the build-size query.
void create_storage(VulkanDevice& device, AccelObject& object, const VkAccelerationStructureBuildGeometryInfoKHR& info,
                    std::uint32_t max_primitives) {
  VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  device.fn().accel_sizes(device.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &max_primitives,
                          &sizes);
  VkPhysicalDeviceAccelerationStructurePropertiesKHR props{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &props};
  vkGetPhysicalDeviceProperties2(device.physical(), &props2);
  const VkDeviceSize scratch_alignment = std::max<VkDeviceSize>(props.minAccelerationStructureScratchOffsetAlignment, 1);

  auto make_buffer = [&](VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name, VkBuffer* buffer,
                         Allocation* memory) {
    VkBufferCreateInfo info_buffer{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info_buffer.size = size;
    info_buffer.usage = usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    device.check_result(vkCreateBuffer(device.device(), &info_buffer, nullptr, buffer), "vkCreateBuffer", name);
    device.set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(*buffer), name);
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device.device(), *buffer, &requirements);
    *memory = device.allocator().allocate(requirements, MemoryUse::GpuOnly, ResourceClass::Buffer, name);
    device.check_result(vkBindBufferMemory(device.device(), *buffer, memory->memory, memory->offset),
                        "vkBindBufferMemory", name);
    VkBufferDeviceAddressInfo address{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    address.buffer = *buffer;
    return vkGetBufferDeviceAddress(device.device(), &address);
  };
  make_buffer(sizes.accelerationStructureSize, VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR, object.name,
              &object.buffer, &object.memory);
  const VkDeviceSize scratch = std::max(sizes.buildScratchSize, sizes.updateScratchSize) + scratch_alignment;
  const VkDeviceAddress base = make_buffer(scratch, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, object.name + " scratch",
                                           &object.scratch, &object.scratch_memory);
  object.scratch_address = (base + scratch_alignment - 1) / scratch_alignment * scratch_alignment;

  VkAccelerationStructureCreateInfoKHR create{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  create.buffer = object.buffer;
  create.size = sizes.accelerationStructureSize;
  create.type = info.type;
  device.check_result(device.fn().create_accel(device.device(), &create, nullptr, &object.handle),
                      "vkCreateAccelerationStructureKHR", object.name);
  device.set_name(VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR, reinterpret_cast<std::uint64_t>(object.handle),
                  object.name);
  VkAccelerationStructureDeviceAddressInfoKHR address{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  address.accelerationStructure = object.handle;
  object.address = device.fn().accel_address(device.device(), &address);
}

}  // namespace

void VulkanDevice::destroy_accel(AccelObject& object) {
  if (object.handle) fn_.destroy_accel(device_, object.handle, nullptr);
  if (object.buffer) vkDestroyBuffer(device_, object.buffer, nullptr);
  if (object.scratch) vkDestroyBuffer(device_, object.scratch, nullptr);
  allocator_->free(object.memory);
  allocator_->free(object.scratch_memory);
  object = AccelObject{};
}

AccelHandle VulkanDevice::create_blas(const BlasDesc& desc) {
  check_alive();
  static_assert(sizeof(VkAabbPositionsKHR) == 24, "hal::validate checks box buffers for 24-byte boxes");
  AccelObject object;
  object.name = desc.name;
  object.blas = desc;
  const auto geometry = blas_geometry(desc, 0, 0, 0);
  VkAccelerationStructureBuildGeometryInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  info.flags = build_flags(desc.allow_update);
  info.geometryCount = 1;
  info.pGeometries = &geometry;
  try {
    create_storage(*this, object, info, desc.primitive_count());
  } catch (...) {
    destroy_accel(object);
    throw;
  }
  return AccelHandle{accels.add(std::move(object))};
}

AccelHandle VulkanDevice::create_tlas(const TlasDesc& desc) {
  check_alive();
  AccelObject object;
  object.name = desc.name;
  object.top = true;
  object.tlas = desc;
  const auto geometry = instances(0);
  VkAccelerationStructureBuildGeometryInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  info.flags = build_flags(desc.allow_update);
  info.geometryCount = 1;
  info.pGeometries = &geometry;
  try {
    create_storage(*this, object, info, desc.max_instances);
  } catch (...) {
    destroy_accel(object);
    throw;
  }
  return AccelHandle{accels.add(std::move(object))};
}

void VulkanDevice::destroy(AccelHandle handle) {
  AccelObject& object = accels.get(handle.id, "acceleration structure");
  destroy_accel(object);
  accels.erase(handle.id);
}

// ---- Recording ----------------------------------------------------------------------------------

void VulkanCommandList::scratch_barrier(VkBuffer scratch) {
  // Successive builds of one structure share its scratch: order them (write-after-write).
  VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  barrier.srcStageMask = barrier.dstStageMask = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR;
  barrier.srcAccessMask = barrier.dstAccessMask =
      VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR | VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
  barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.buffer = scratch;
  barrier.size = VK_WHOLE_SIZE;
  VkDependencyInfo info{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  info.bufferMemoryBarrierCount = 1;
  info.pBufferMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd_, &info);
}

void VulkanCommandList::record_build(VkCommandBuffer cmd, AccelObject& object,
                                     const VkAccelerationStructureGeometryKHR& geometry, std::uint32_t primitives,
                                     bool allow_update, bool update) {
  VkAccelerationStructureBuildGeometryInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = object.top ? VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR : VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  info.flags = build_flags(allow_update);
  info.mode = update ? VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR : VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.srcAccelerationStructure = update ? object.handle : VK_NULL_HANDLE;
  info.dstAccelerationStructure = object.handle;
  info.geometryCount = 1;
  info.pGeometries = &geometry;
  info.scratchData.deviceAddress = object.scratch_address;
  VkAccelerationStructureBuildRangeInfoKHR range{primitives, 0, 0, 0};
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
  scratch_barrier(object.scratch);
  device_.fn().cmd_build_accel(cmd, 1, &info, &ranges);
}

void VulkanCommandList::build_blas(AccelHandle handle, bool update) {
  VkCommandBuffer cmd = recording();
  AccelObject& object = device_.accels.get(handle.id, "acceleration structure");
  const BlasDesc& desc = object.blas;
  auto address = [&](BufferHandle b) { return b ? device_.buffers.get(b.id, "buffer").address : VkDeviceAddress{0}; };
  const auto geometry = blas_geometry(desc, address(desc.vertices), address(desc.indices), address(desc.boxes));
  record_build(cmd, object, geometry, desc.primitive_count(), desc.allow_update, update);
}

void VulkanCommandList::build_tlas(AccelHandle handle, std::span<const TlasInstance> list, bool update) {
  VkCommandBuffer cmd = recording();
  AccelObject& object = device_.accels.get(handle.id, "acceleration structure");

  // Instances are copied now into the upload ring, which the build reads by device address.
  std::vector<VkAccelerationStructureInstanceKHR> data(std::max<std::size_t>(list.size(), 1));
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TlasInstance& in = list[i];
    const AccelObject& blas = device_.accels.get(in.blas.id, "acceleration structure");
    VkAccelerationStructureInstanceKHR& out = data[i];
    std::memcpy(out.transform.matrix, in.transform.data(), sizeof(out.transform.matrix));  // both row-major 3x4
    out.instanceCustomIndex = in.custom_index;
    out.mask = in.mask;
    out.instanceShaderBindingTableRecordOffset = 0;
    out.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;
    out.accelerationStructureReference = blas.address;
  }
  const VkDeviceSize offset = upload(data.data(), data.size() * sizeof(data[0]), 16);
  const auto geometry = instances(device_.ring().address + offset);
  record_build(cmd, object, geometry, static_cast<std::uint32_t>(list.size()), object.tlas.allow_update, update);
}

}  // namespace hal::vulkan
