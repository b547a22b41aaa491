// Device memory: a range allocator (pure logic, unit-tested without a GPU) and the Vulkan memory
// allocator that sub-allocates resources from large VkDeviceMemory blocks with it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace hal::vulkan {

// Best-fit allocator over [0, capacity): aligned sub-ranges, coalescing on free. Alignment padding
// stays free, so it can be reused by smaller allocations.
class RangeAllocator {
 public:
  explicit RangeAllocator(std::uint64_t capacity);

  // Offset of a new range of `size` bytes aligned to `alignment` (a power of two), or nullopt.
  std::optional<std::uint64_t> allocate(std::uint64_t size, std::uint64_t alignment);
  // Frees a range by the offset allocate() returned; returns false for an unknown offset.
  bool free(std::uint64_t offset);

  std::uint64_t capacity() const { return capacity_; }
  std::uint64_t used() const { return used_bytes_; }
  bool empty() const { return used_.empty(); }
  std::size_t free_range_count() const { return free_.size(); }
  std::uint64_t largest_free_range() const;

 private:
  std::uint64_t capacity_;
  std::uint64_t used_bytes_ = 0;
  std::map<std::uint64_t, std::uint64_t> free_;            // offset -> size, never adjacent
  std::unordered_map<std::uint64_t, std::uint64_t> used_;  // offset -> size
};

enum class MemoryUse : std::uint8_t {
  GpuOnly,   // device-local resources
  Upload,    // host writes, GPU reads (staging, uniform ring, TLAS instances)
  Readback,  // GPU writes, host reads
};
// Buffers and optimal-tiling images live in separate blocks, so bufferImageGranularity never matters.
enum class ResourceClass : std::uint8_t { Buffer, Image };

struct Allocation {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
  std::byte* mapped = nullptr;  // non-null for host-visible memory (persistently mapped)
  int pool = -1;                // -1: a dedicated VkDeviceMemory
  std::uint32_t block = 0;
  explicit operator bool() const { return memory != VK_NULL_HANDLE; }
};

class MemoryAllocator {
 public:
  MemoryAllocator(VkPhysicalDevice physical, VkDevice device, bool device_address,
                  VkDeviceSize block_size = VkDeviceSize{64} << 20);
  ~MemoryAllocator();
  MemoryAllocator(const MemoryAllocator&) = delete;
  MemoryAllocator& operator=(const MemoryAllocator&) = delete;

  // Throws hal::Error(OutOfMemory) naming `object` when no memory can be found.
  Allocation allocate(const VkMemoryRequirements& requirements, MemoryUse use, ResourceClass cls,
                      std::string_view object);
  void free(const Allocation& allocation);

  // Size of the largest memory heap, for rejecting impossible requests before asking the driver.
  VkDeviceSize largest_heap() const;
  // Bytes of VkDeviceMemory allocated now (blocks and dedicated allocations).
  VkDeviceSize device_memory() const { return device_memory_; }

 private:
  struct Block {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    std::byte* mapped = nullptr;
    std::unique_ptr<RangeAllocator> ranges;
  };
  struct Pool {
    std::uint32_t type = 0;
    ResourceClass cls = ResourceClass::Buffer;
    std::vector<Block> blocks;  // a freed block leaves a null entry so indices stay stable
  };
  std::uint32_t choose_type(std::uint32_t type_bits, MemoryUse use, std::string_view object) const;
  VkDeviceMemory allocate_memory(VkDeviceSize size, std::uint32_t type, std::string_view object, std::byte** mapped);

  VkDevice device_;
  bool device_address_;
  VkDeviceSize block_size_;
  VkPhysicalDeviceMemoryProperties props_{};
  std::vector<Pool> pools_;
  VkDeviceSize device_memory_ = 0;
};

}  // namespace hal::vulkan
