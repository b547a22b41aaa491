// The Vulkan device behind hal::Device: the objects it owns and the state command lists share.
// Member functions are defined by concern: device.cpp (creation, submit, wait, destroy),
// resources.cpp (buffers, images), transfer.cpp (host uploads and readbacks), pipeline.cpp,
// binding_set.cpp, accel.cpp, timers.cpp.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>

#include "hal/device.hpp"
#include "hal/error.hpp"
#include "hal_vulkan/interop.hpp"
#include "hal_vulkan/vulkan.hpp"
#include "instance.hpp"
#include "memory.hpp"

namespace hal::vulkan {

// ---- Objects ----------------------------------------------------------------------------------

struct BufferObject {
  std::string name;
  BufferDesc desc;
  VkBuffer buffer = VK_NULL_HANDLE;
  Allocation memory;
  VkDeviceAddress address = 0;  // 0 unless the buffer is an acceleration-structure build input
};

struct ImageObject {
  std::string name;
  ImageDesc desc;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  Allocation memory;
  bool owned = true;  // false: imported (hal_vulkan/interop.hpp); only the view is ours
};

struct PipelineObject {
  std::string name;
  const ShaderInfo* shader = nullptr;
  std::vector<VkDescriptorSetLayout> set_layouts;  // one per set index 0..max used
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  const ShaderBinding* uniform = nullptr;  // the uniform block, bound from DispatchDesc::uniforms
};

struct BindingSetObject {
  std::string name;
  PipelineHandle pipeline;
  const ShaderInfo* shader = nullptr;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets;  // parallel to the pipeline's set layouts
  std::vector<Resource> bound;        // parallel to shader->bindings; id 0: not bound
};

struct AccelObject {
  std::string name;
  bool top = false;
  BlasDesc blas;
  TlasDesc tlas;
  VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
  VkBuffer buffer = VK_NULL_HANDLE;  // storage of the structure
  Allocation memory;
  VkDeviceAddress address = 0;
  VkBuffer scratch = VK_NULL_HANDLE;  // build and update scratch, owned by the structure
  Allocation scratch_memory;
  VkDeviceAddress scratch_address = 0;  // aligned for minAccelerationStructureScratchOffsetAlignment
};

struct TimerObject {
  std::string name;
  VkQueryPool pool = VK_NULL_HANDLE;
  std::uint32_t regions = 0;
  std::vector<bool> submitted;  // region was written by a submitted command list
};

// Objects by handle id. Ids are never reused, so a destroyed handle is always reported.
template <typename T>
class Table {
 public:
  std::uint32_t add(T object) {
    const std::uint32_t id = ++last_;
    objects_.emplace(id, std::move(object));
    return id;
  }
  T* find(std::uint32_t id) {
    const auto it = objects_.find(id);
    return it == objects_.end() ? nullptr : &it->second;
  }
  T& get(std::uint32_t id, std::string_view what) {
    if (T* object = find(id)) return *object;
    throw Error(ErrorKind::InvalidHandle, std::string(what) + " #" + std::to_string(id),
                id == 0 ? "the handle is empty (never created)" : "the handle was destroyed or never created");
  }
  void erase(std::uint32_t id) { objects_.erase(id); }
  std::unordered_map<std::uint32_t, T>& all() { return objects_; }

 private:
  std::uint32_t last_ = 0;
  std::unordered_map<std::uint32_t, T> objects_;
};

// Extension entry points, loaded once per device (null when the extension is not enabled).
struct DeviceFunctions {
  PFN_vkCreateAccelerationStructureKHR create_accel = nullptr;
  PFN_vkDestroyAccelerationStructureKHR destroy_accel = nullptr;
  PFN_vkGetAccelerationStructureBuildSizesKHR accel_sizes = nullptr;
  PFN_vkGetAccelerationStructureDeviceAddressKHR accel_address = nullptr;
  PFN_vkCmdBuildAccelerationStructuresKHR cmd_build_accel = nullptr;
  PFN_vkCmdBeginDebugUtilsLabelEXT begin_label = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT end_label = nullptr;
  PFN_vkSetDebugUtilsObjectNameEXT set_name = nullptr;
};

// Host-visible buffer from which command lists take chunks for uniform data and TLAS instances.
// Descriptor sets point their dynamic uniform buffer at it, so it is one buffer for the device.
struct UploadRing {
  VkBuffer buffer = VK_NULL_HANDLE;
  Allocation memory;
  VkDeviceAddress address = 0;
  VkDeviceSize size = 0;
  std::unique_ptr<RangeAllocator> ranges;
};

// ---- Device -----------------------------------------------------------------------------------

class VulkanCommandList;

class VulkanDevice final : public hal::Device {
 public:
  explicit VulkanDevice(const DeviceOptions& options);
  // On the caller's objects (hal_vulkan/interop.hpp): nothing of theirs is destroyed.
  explicit VulkanDevice(const ExternalDevice& external);
  ~VulkanDevice() override;

  const AdapterInfo& adapter() const override { return adapter_.info; }
  const Capabilities& capabilities() const override { return adapter_.capabilities; }

  BufferHandle create_buffer(const BufferDesc& desc) override;
  ImageHandle create_image(const ImageDesc& desc) override;
  PipelineHandle create_pipeline(const ComputePipelineDesc& desc) override;
  BindingSetHandle create_binding_set(const BindingSetDesc& desc) override;
  AccelHandle create_blas(const BlasDesc& desc) override;
  AccelHandle create_tlas(const TlasDesc& desc) override;
  TimerQueriesHandle create_timer_queries(const TimerQueriesDesc& desc) override;
  std::unique_ptr<CommandList> create_command_list(std::string_view name) override;

  void destroy(BufferHandle handle) override;
  void destroy(ImageHandle handle) override;
  void destroy(PipelineHandle handle) override;
  void destroy(BindingSetHandle handle) override;
  void destroy(AccelHandle handle) override;
  void destroy(TimerQueriesHandle handle) override;

  void submit(CommandList& commands) override;
  void wait() override;

  void upload_buffer(BufferHandle dst, std::uint64_t offset, std::span<const std::byte> data) override;
  void read_buffer(BufferHandle src, std::uint64_t offset, std::span<std::byte> out) override;
  void upload_image(ImageHandle dst, std::span<const std::byte> data) override;
  void read_image(ImageHandle src, std::span<std::byte> out) override;

  std::vector<std::optional<double>> read_timers(TimerQueriesHandle timers) override;
  std::optional<std::uint64_t> device_memory_bytes() const override { return allocator_->device_memory(); }

  // ---- Shared with command lists and the presenter ----
  VkDevice device() const { return device_; }
  VkPhysicalDevice physical() const { return physical_; }
  VkInstance instance() const { return instance_->handle(); }
  VkQueue queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  const DeviceFunctions& fn() const { return fn_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }
  MemoryAllocator& allocator() { return *allocator_; }
  UploadRing& ring() { return ring_; }
  bool swapchain_enabled() const { return swapchain_; }
  std::uint32_t timestamp_bits() const { return timestamp_bits_; }

  Table<BufferObject> buffers;
  Table<ImageObject> images;
  Table<PipelineObject> pipelines;
  Table<BindingSetObject> binding_sets;
  Table<AccelObject> accels;
  Table<TimerObject> timers;

  // Submission serials: a command list may be reset once completed_serial() reaches its serial.
  std::uint64_t submitted_serial() const { return submitted_; }
  std::uint64_t completed_serial() const { return completed_; }
  // Throws DeviceLost once the device has been lost; every entry point calls it first.
  void check_alive() const;
  // check() that also remembers device loss.
  void check_result(VkResult result, std::string_view call, std::string_view object);
  // Gives a Vulkan object a debug name (shown in validation messages and captures).
  void set_name(VkObjectType type, std::uint64_t handle, const std::string& name) const;

  // The caller's image as a HAL image (interop.hpp).
  ImageHandle import_image(VkImage image, VkFormat format, std::uint32_t width, std::uint32_t height, ImageUsage usage,
                           std::string_view name);

  // One-shot command buffer for host transfers: records with `record`, submits, waits.
  template <typename F>
  void run_now(std::string_view what, F&& record);

 private:
  void create_logical_device(const DeviceOptions& options);
  // The physical device's limits; throws Unsupported below Vulkan 1.3.
  void read_limits();
  // After the device exists: extension entry points, allocator, transfer pool, upload ring.
  void load_functions();
  void create_shared_objects();
  VkCommandBuffer begin_transfer();
  void finish_transfer(VkCommandBuffer cmd, std::string_view what);
  // A host-visible staging buffer of `size` bytes (usage transfer src and dst).
  std::pair<VkBuffer, Allocation> create_staging(VkDeviceSize size, MemoryUse use, std::string_view object);
  void destroy_accel(AccelObject& object);

  std::unique_ptr<Instance> instance_;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  AdapterReport adapter_;
  VkPhysicalDeviceLimits limits_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queue_family_ = 0;
  DeviceFunctions fn_;
  bool swapchain_ = false;
  bool pipeline_stats_ = false;  // ASVGF_VK_PIPELINE_STATS on a device with the extension (pipeline_stats.hpp)
  std::uint32_t timestamp_bits_ = 0;
  std::unique_ptr<MemoryAllocator> allocator_;
  UploadRing ring_;
  VkCommandPool transfer_pool_ = VK_NULL_HANDLE;
  std::uint64_t submitted_ = 0, completed_ = 0;
  bool lost_ = false;
  bool owns_device_ = true;  // false on the caller's VkDevice (interop)
};

template <typename F>
void VulkanDevice::run_now(std::string_view what, F&& record) {
  VkCommandBuffer cmd = begin_transfer();
  try {
    record(cmd);
  } catch (...) {
    vkEndCommandBuffer(cmd);
    vkFreeCommandBuffers(device_, transfer_pool_, 1, &cmd);
    throw;
  }
  finish_transfer(cmd, what);
}

// ---- Helpers shared across files ----------------------------------------------------------------
VkFormat to_vk(Format format);
VkBufferUsageFlags to_vk(BufferUsage usage, bool device_address);
std::string describe_bytes(std::uint64_t bytes);

}  // namespace hal::vulkan
