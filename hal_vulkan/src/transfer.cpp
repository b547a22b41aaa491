// Synchronous host transfers through staging buffers. Each one is its own submission that waits
// for the queue to drain; barriers at both ends order it against earlier and later submissions.
#include <cstring>

#include "check.hpp"
#include "device.hpp"

namespace hal::vulkan {
namespace {

// Earlier submissions' accesses complete (and writes are visible) before the transfer.
void before_transfer(VkCommandBuffer cmd) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  barrier.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT;
  VkDependencyInfo info{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  info.memoryBarrierCount = 1;
  info.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &info);
}

// Transfer writes into staging memory become visible to the host.
void transfer_to_host(VkCommandBuffer cmd) {
  VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  barrier.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  barrier.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  barrier.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  VkDependencyInfo info{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  info.memoryBarrierCount = 1;
  info.pMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &info);
}

// Releases a staging buffer when the transfer using it ends, normally or by an exception.
struct StagingRelease {
  VkDevice device;
  MemoryAllocator& allocator;
  VkBuffer buffer;
  Allocation memory;
  ~StagingRelease() {
    vkDestroyBuffer(device, buffer, nullptr);
    allocator.free(memory);
  }
};

}  // namespace

std::pair<VkBuffer, Allocation> VulkanDevice::create_staging(VkDeviceSize size, MemoryUse use, std::string_view object) {
  const std::string name = "staging for " + std::string(object);
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  check_result(vkCreateBuffer(device_, &info, nullptr, &buffer), "vkCreateBuffer", name);
  set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(buffer), name);
  Allocation memory;
  try {
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer, &requirements);
    memory = allocator_->allocate(requirements, use, ResourceClass::Buffer, name);
    check_result(vkBindBufferMemory(device_, buffer, memory.memory, memory.offset), "vkBindBufferMemory", name);
  } catch (...) {
    vkDestroyBuffer(device_, buffer, nullptr);
    allocator_->free(memory);
    throw;
  }
  return {buffer, memory};
}

void VulkanDevice::upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) {
  check_alive();
  const BufferObject& b = buffers.get(dst.id, "buffer");
  if (data.empty()) return;
  auto [staging, memory] = create_staging(data.size(), MemoryUse::Upload, b.name);
  const StagingRelease release{device_, *allocator_, staging, memory};
  std::memcpy(memory.mapped, data.data(), data.size());
  run_now(b.name, [&, staging = staging](VkCommandBuffer cmd) {
    before_transfer(cmd);
    const VkBufferCopy region{0, offset, data.size()};
    vkCmdCopyBuffer(cmd, staging, b.buffer, 1, &region);
  });
}

void VulkanDevice::read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) {
  check_alive();
  const BufferObject& b = buffers.get(src.id, "buffer");
  if (out.empty()) return;
  auto [staging, memory] = create_staging(out.size(), MemoryUse::Readback, b.name);
  const StagingRelease release{device_, *allocator_, staging, memory};
  run_now(b.name, [&, staging = staging](VkCommandBuffer cmd) {
    before_transfer(cmd);
    const VkBufferCopy region{offset, 0, out.size()};
    vkCmdCopyBuffer(cmd, b.buffer, staging, 1, &region);
    transfer_to_host(cmd);
  });
  std::memcpy(out.data(), memory.mapped, out.size());
}

void VulkanDevice::upload_image(ImageHandle dst, std::span<const std::byte> data) {
  check_alive();
  const ImageObject& i = images.get(dst.id, "image");
  const std::uint64_t bytes = data.size();  // the whole image (checked by hal::validate)
  auto [staging, memory] = create_staging(bytes, MemoryUse::Upload, i.name);
  const StagingRelease release{device_, *allocator_, staging, memory};
  std::memcpy(memory.mapped, data.data(), bytes);
  run_now(i.name, [&, staging = staging](VkCommandBuffer cmd) {
    // The whole image is overwritten, so its previous layout and contents do not matter.
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    barrier.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = i.image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo info{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    info.imageMemoryBarrierCount = 1;
    info.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &info);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {i.desc.width, i.desc.height, 1};
    vkCmdCopyBufferToImage(cmd, staging, i.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  });
}

void VulkanDevice::read_image(ImageHandle src, std::span<std::byte> out) {
  check_alive();
  const ImageObject& i = images.get(src.id, "image");
  const std::uint64_t bytes = out.size();  // the whole image (checked by hal::validate)
  auto [staging, memory] = create_staging(bytes, MemoryUse::Readback, i.name);
  const StagingRelease release{device_, *allocator_, staging, memory};
  run_now(i.name, [&, staging = staging](VkCommandBuffer cmd) {
    before_transfer(cmd);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {i.desc.width, i.desc.height, 1};
    vkCmdCopyImageToBuffer(cmd, i.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging, 1, &region);
    transfer_to_host(cmd);
  });
  std::memcpy(out.data(), memory.mapped, bytes);
}

}  // namespace hal::vulkan
