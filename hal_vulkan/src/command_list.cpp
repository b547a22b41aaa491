// Command recording: lifecycle, labels, barriers (HAL states to sync2), copies, clears, dispatch.
#include "command_list.hpp"

#include <cstring>

#include "check.hpp"

namespace hal::vulkan {
namespace {

constexpr VkDeviceSize kChunkSize = 64 * 1024;

void dependency(VkCommandBuffer cmd, const std::vector<VkMemoryBarrier2>& memory,
                const std::vector<VkBufferMemoryBarrier2>& buffers, const std::vector<VkImageMemoryBarrier2>& images) {
  if (memory.empty() && buffers.empty() && images.empty()) return;
  VkDependencyInfo info{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  info.memoryBarrierCount = static_cast<std::uint32_t>(memory.size());
  info.pMemoryBarriers = memory.data();
  info.bufferMemoryBarrierCount = static_cast<std::uint32_t>(buffers.size());
  info.pBufferMemoryBarriers = buffers.data();
  info.imageMemoryBarrierCount = static_cast<std::uint32_t>(images.size());
  info.pImageMemoryBarriers = images.data();
  vkCmdPipelineBarrier2(cmd, &info);
}

}  // namespace

StateInfo state_info(State state) {
  switch (state) {
    case State::Undefined:
      return {};
    // GENERAL for every shader state: storage images are read and written in it, and sampled
    // reads of an image that was just a storage image need no layout change.
    case State::ShaderRead:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT,
              VK_IMAGE_LAYOUT_GENERAL};
    case State::ShaderWrite:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case State::CopySrc:
      return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    case State::CopyDst:
      return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
    case State::AccelBuildInput:
      return {VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, VK_ACCESS_2_SHADER_READ_BIT,
              VK_IMAGE_LAYOUT_UNDEFINED};
    case State::AccelWrite:
      return {VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
              VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR | VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
              VK_IMAGE_LAYOUT_UNDEFINED};
    case State::AccelRead:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
              VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR, VK_IMAGE_LAYOUT_UNDEFINED};
    // A HAL image "presented" is the source of the presenter's blit into the swapchain image.
    case State::Present:
      return {VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
  }
  return {};
}

VulkanCommandList::VulkanCommandList(VulkanDevice& device, std::string name) : device_(device), name_(std::move(name)) {
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.queueFamilyIndex = device_.queue_family();
  device_.check_result(vkCreateCommandPool(device_.device(), &pool, nullptr, &pool_), "vkCreateCommandPool", name_);
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  const VkResult result = vkAllocateCommandBuffers(device_.device(), &alloc, &cmd_);
  if (result != VK_SUCCESS) vkDestroyCommandPool(device_.device(), pool_, nullptr);
  device_.check_result(result, "vkAllocateCommandBuffers", name_);
  device_.set_name(VK_OBJECT_TYPE_COMMAND_BUFFER, reinterpret_cast<std::uint64_t>(cmd_), name_);
}

VulkanCommandList::VulkanCommandList(VulkanDevice& device, std::string name, VkCommandBuffer external)
    : device_(device), name_(std::move(name)), cmd_(external), phase_(Phase::Recording), external_(true) {
  if (!external) throw Error(ErrorKind::InvalidDescriptor, name_, "the command buffer to wrap is VK_NULL_HANDLE");
}

VulkanCommandList::~VulkanCommandList() {
  // The device may still execute it: a destructor cannot report, so it waits.
  if (serial_ > device_.completed_serial()) vkQueueWaitIdle(device_.queue());
  release_chunks();
  if (!external_) vkDestroyCommandPool(device_.device(), pool_, nullptr);
}

void VulkanCommandList::reset() {
  device_.check_alive();
  // A wrapped command buffer is the caller's to reset; here only what the HAL holds for it is freed.
  if (!external_) device_.check_result(vkResetCommandPool(device_.device(), pool_, 0), "vkResetCommandPool", name_);
  release_chunks();
  timer_writes_.clear();
  phase_ = external_ ? Phase::Recording : Phase::Initial;
}

VkCommandBuffer VulkanCommandList::recording() {
  device_.check_alive();
  if (phase_ == Phase::Initial) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    device_.check_result(vkBeginCommandBuffer(cmd_, &begin), "vkBeginCommandBuffer", name_);
    phase_ = Phase::Recording;
  }
  return cmd_;
}

VkCommandBuffer VulkanCommandList::end_for_submit() {
  if (external_)
    throw Error(ErrorKind::InvalidUsage, name_, "a wrapped command buffer is ended and submitted by its owner");
  if (phase_ != Phase::Executable) {
    recording();
    device_.check_result(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer", name_);
    phase_ = Phase::Executable;
  }
  return cmd_;
}

void VulkanCommandList::mark_submitted(std::uint64_t serial) {
  serial_ = serial;
  for (const auto& [id, region] : timer_writes_)
    if (TimerObject* t = device_.timers.find(id)) t->submitted[region] = true;
}

VkDeviceSize VulkanCommandList::upload(const void* bytes, VkDeviceSize size, VkDeviceSize alignment) {
  VkDeviceSize offset = (chunk_begin_ + chunk_used_ + alignment - 1) / alignment * alignment;
  if (chunk_size_ == 0 || offset + size > chunk_begin_ + chunk_size_) {
    const VkDeviceSize chunk = std::max(kChunkSize, size + alignment);
    const auto begin = device_.ring().ranges->allocate(chunk, 256);
    if (!begin)
      throw Error(ErrorKind::OutOfMemory, name_,
                  "the device's upload ring (" + describe_bytes(device_.ring().size) +
                      ") for uniforms and TLAS instances is full: submit and wait() more often");
    chunks_.push_back(*begin);
    chunk_begin_ = *begin;
    chunk_size_ = chunk;
    chunk_used_ = 0;
    offset = (chunk_begin_ + alignment - 1) / alignment * alignment;
  }
  std::memcpy(device_.ring().memory.mapped + offset, bytes, size);
  chunk_used_ = offset + size - chunk_begin_;
  return offset;
}

void VulkanCommandList::release_chunks() {
  for (const VkDeviceSize begin : chunks_) device_.ring().ranges->free(begin);
  chunks_.clear();
  chunk_begin_ = chunk_used_ = chunk_size_ = 0;
}

void VulkanCommandList::begin_label(std::string_view label) {
  VkCommandBuffer cmd = recording();
  if (!device_.fn().begin_label) return;
  const std::string text(label);
  VkDebugUtilsLabelEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
  info.pLabelName = text.c_str();
  device_.fn().begin_label(cmd, &info);
}

void VulkanCommandList::end_label() {
  VkCommandBuffer cmd = recording();
  if (device_.fn().end_label) device_.fn().end_label(cmd);
}

void VulkanCommandList::barrier(std::span<const Barrier> barriers) {
  VkCommandBuffer cmd = recording();
  std::vector<VkMemoryBarrier2> memory;
  std::vector<VkBufferMemoryBarrier2> buffers;
  std::vector<VkImageMemoryBarrier2> images;
  for (const Barrier& b : barriers) {
    const StateInfo src = state_info(b.before), dst = state_info(b.after);
    switch (b.resource.kind) {
      case ResourceKind::Buffer: {
        const BufferObject& object = device_.buffers.get(b.resource.id, "buffer");
        VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        barrier.srcStageMask = src.stages;
        barrier.srcAccessMask = src.access;
        barrier.dstStageMask = dst.stages;
        barrier.dstAccessMask = dst.access;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.buffer = object.buffer;
        barrier.size = VK_WHOLE_SIZE;
        buffers.push_back(barrier);
        break;
      }
      case ResourceKind::Image: {
        const ImageObject& object = device_.images.get(b.resource.id, "image");
        VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        barrier.srcStageMask = src.stages;
        barrier.srcAccessMask = src.access;
        barrier.dstStageMask = dst.stages;
        barrier.dstAccessMask = dst.access;
        barrier.oldLayout = b.discard ? VK_IMAGE_LAYOUT_UNDEFINED : src.layout;
        barrier.newLayout = dst.layout;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = object.image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        images.push_back(barrier);
        break;
      }
      case ResourceKind::Accel: {
        // Acceleration structures live in buffers; a global barrier also covers their scratch.
        device_.accels.get(b.resource.id, "acceleration structure");
        auto accel_state = [](State s) { return state_info(s == State::ShaderRead ? State::AccelRead : s); };
        const StateInfo from = accel_state(b.before), to = accel_state(b.after);
        VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        barrier.srcStageMask = from.stages;
        barrier.srcAccessMask = from.access;
        barrier.dstStageMask = to.stages;
        barrier.dstAccessMask = to.access;
        memory.push_back(barrier);
        break;
      }
    }
  }
  dependency(cmd, memory, buffers, images);
}

void VulkanCommandList::dispatch(const DispatchDesc& desc) {
  VkCommandBuffer cmd = recording();
  const PipelineObject& pipeline = device_.pipelines.get(desc.pipeline.id, "pipeline");
  const BindingSetObject& set = device_.binding_sets.get(desc.bindings.id, "binding set");
  const auto& max = device_.limits().maxComputeWorkGroupCount;
  if (desc.groups_x > max[0] || desc.groups_y > max[1] || desc.groups_z > max[2])
    throw Error(ErrorKind::InvalidUsage, pipeline.name,
                "dispatch of " + std::to_string(desc.groups_x) + "x" + std::to_string(desc.groups_y) + "x" +
                    std::to_string(desc.groups_z) + " groups exceeds the device's limit");

  std::uint32_t dynamic_offset = 0;
  if (pipeline.uniform) {
    const VkDeviceSize alignment = std::max<VkDeviceSize>(device_.limits().minUniformBufferOffsetAlignment, 16);
    dynamic_offset = static_cast<std::uint32_t>(upload(desc.uniforms.data(), desc.uniforms.size(), alignment));
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout, 0,
                          static_cast<std::uint32_t>(set.sets.size()), set.sets.data(), pipeline.uniform ? 1 : 0,
                          &dynamic_offset);
  vkCmdDispatch(cmd, desc.groups_x, desc.groups_y, desc.groups_z);
}

void VulkanCommandList::copy_buffer(const BufferCopy& copy) {
  VkCommandBuffer cmd = recording();
  const BufferObject& src = device_.buffers.get(copy.src.id, "buffer");
  const BufferObject& dst = device_.buffers.get(copy.dst.id, "buffer");
  const VkBufferCopy region{copy.src_offset, copy.dst_offset, copy.size};
  vkCmdCopyBuffer(cmd, src.buffer, dst.buffer, 1, &region);
}

void VulkanCommandList::copy_image(ImageHandle src_handle, ImageHandle dst_handle) {
  VkCommandBuffer cmd = recording();
  const ImageObject& src = device_.images.get(src_handle.id, "image");
  const ImageObject& dst = device_.images.get(dst_handle.id, "image");
  VkImageCopy region{};
  region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.extent = {src.desc.width, src.desc.height, 1};
  vkCmdCopyImage(cmd, src.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 1, &region);
}

namespace {
VkBufferImageCopy whole_image(const ImageObject& image) {
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {image.desc.width, image.desc.height, 1};
  return region;
}
}  // namespace

void VulkanCommandList::copy_buffer_to_image(BufferHandle src_handle, ImageHandle dst_handle) {
  VkCommandBuffer cmd = recording();
  const BufferObject& src = device_.buffers.get(src_handle.id, "buffer");
  const ImageObject& dst = device_.images.get(dst_handle.id, "image");
  const VkBufferImageCopy region = whole_image(dst);
  vkCmdCopyBufferToImage(cmd, src.buffer, dst.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
}

void VulkanCommandList::copy_image_to_buffer(ImageHandle src_handle, BufferHandle dst_handle) {
  VkCommandBuffer cmd = recording();
  const ImageObject& src = device_.images.get(src_handle.id, "image");
  const BufferObject& dst = device_.buffers.get(dst_handle.id, "buffer");
  const VkBufferImageCopy region = whole_image(src);
  vkCmdCopyImageToBuffer(cmd, src.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.buffer, 1, &region);
}

void VulkanCommandList::clear_buffer(BufferHandle handle, std::uint32_t word) {
  VkCommandBuffer cmd = recording();
  const BufferObject& b = device_.buffers.get(handle.id, "buffer");
  vkCmdFillBuffer(cmd, b.buffer, 0, VK_WHOLE_SIZE, word);
}

void VulkanCommandList::clear_image(ImageHandle handle, std::array<float, 4> value) {
  VkCommandBuffer cmd = recording();
  const ImageObject& i = device_.images.get(handle.id, "image");
  VkClearColorValue color{};
  const bool integer = format_is_uint(i.desc.format);
  for (int c = 0; c < 4; ++c) {
    if (integer)
      color.uint32[c] = value[c] <= 0.0f ? 0u : static_cast<std::uint32_t>(value[c]);
    else
      color.float32[c] = value[c];
  }
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, i.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1, &range);
}

}  // namespace hal::vulkan
