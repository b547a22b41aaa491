// The Vulkan command list: one primary command buffer plus the upload-ring chunks it wrote.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <utility>
#include <vector>

#include "device.hpp"
#include "hal/command_list.hpp"

namespace hal::vulkan {

// Stage, access and image layout of a HAL state (used by barriers and the presenter).
struct StateInfo {
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};
StateInfo state_info(State state);

class VulkanCommandList final : public hal::CommandList {
 public:
  VulkanCommandList(VulkanDevice& device, std::string name);
  // Records into the caller's command buffer, already begun (interop.hpp): never begun, ended,
  // reset or submitted here.
  VulkanCommandList(VulkanDevice& device, std::string name, VkCommandBuffer external);
  ~VulkanCommandList() override;

  void reset() override;
  void begin_label(std::string_view label) override;
  void end_label() override;
  void barrier(std::span<const Barrier> barriers) override;
  void dispatch(const DispatchDesc& desc) override;
  void copy_buffer(const BufferCopy& copy) override;
  void copy_image(ImageHandle src, ImageHandle dst) override;
  void copy_buffer_to_image(BufferHandle src, ImageHandle dst) override;
  void copy_image_to_buffer(ImageHandle src, BufferHandle dst) override;
  void clear_buffer(BufferHandle buffer, std::uint32_t word) override;
  void clear_image(ImageHandle image, std::array<float, 4> value) override;
  void build_blas(AccelHandle blas, bool update) override;
  void build_tlas(AccelHandle tlas, std::span<const TlasInstance> instances, bool update) override;
  void begin_timer(TimerQueriesHandle timers, std::uint32_t region) override;
  void end_timer(TimerQueriesHandle timers, std::uint32_t region) override;

  // ---- For the device and the presenter ----
  VulkanDevice& device() const { return device_; }
  const std::string& name() const { return name_; }
  // The command buffer, open for recording (begins it if needed).
  VkCommandBuffer recording();
  // Ends recording (if open) and returns the command buffer to submit.
  VkCommandBuffer end_for_submit();
  void mark_submitted(std::uint64_t serial);

 private:
  // Copies `bytes` into the upload ring; returns the ring offset.
  VkDeviceSize upload(const void* bytes, VkDeviceSize size, VkDeviceSize alignment);
  void release_chunks();
  void scratch_barrier(VkBuffer scratch);
  // The timer object of `handle`, after checking that `region` is one of its regions.
  TimerObject& timer_region(TimerQueriesHandle handle, std::uint32_t region);
  // Records one build or update of `object` (BLAS or TLAS) from `geometry`, after its scratch barrier.
  void record_build(VkCommandBuffer cmd, AccelObject& object, const VkAccelerationStructureGeometryKHR& geometry,
                    std::uint32_t primitives, bool allow_update, bool update);

  enum class Phase { Initial, Recording, Executable };
  VulkanDevice& device_;
  std::string name_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  Phase phase_ = Phase::Initial;
  bool external_ = false;     // the caller's command buffer: no pool of ours
  std::uint64_t serial_ = 0;  // submission serial of the last submit; 0: never submitted
  std::vector<VkDeviceSize> chunks_;  // ring ranges this list owns
  VkDeviceSize chunk_begin_ = 0, chunk_used_ = 0, chunk_size_ = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> timer_writes_;  // (timer id, region)
};

}  // namespace hal::vulkan
