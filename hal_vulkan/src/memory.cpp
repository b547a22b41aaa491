#include "memory.hpp"

#include <limits>
#include <string>

#include "check.hpp"

namespace hal::vulkan {

// ---- RangeAllocator ---------------------------------------------------------------------------

RangeAllocator::RangeAllocator(std::uint64_t capacity) : capacity_(capacity) {
  if (capacity > 0) free_.emplace(0, capacity);
}

std::optional<std::uint64_t> RangeAllocator::allocate(std::uint64_t size, std::uint64_t alignment) {
  if (size == 0 || alignment == 0 || (alignment & (alignment - 1)) != 0) return std::nullopt;
  // Best fit: the smallest free range that holds the aligned request, to keep large ranges whole.
  auto best = free_.end();
  std::uint64_t best_size = std::numeric_limits<std::uint64_t>::max();
  for (auto it = free_.begin(); it != free_.end(); ++it) {
    const std::uint64_t aligned = (it->first + alignment - 1) & ~(alignment - 1);
    const std::uint64_t padding = aligned - it->first;
    if (padding >= it->second || it->second - padding < size) continue;
    if (it->second < best_size) {
      best = it;
      best_size = it->second;
    }
  }
  if (best == free_.end()) return std::nullopt;

  const std::uint64_t begin = best->first, length = best->second;
  const std::uint64_t offset = (begin + alignment - 1) & ~(alignment - 1);
  free_.erase(best);
  if (offset > begin) free_.emplace(begin, offset - begin);  // padding stays free
  if (offset + size < begin + length) free_.emplace(offset + size, begin + length - (offset + size));
  used_.emplace(offset, size);
  used_bytes_ += size;
  return offset;
}

bool RangeAllocator::free(std::uint64_t offset) {
  const auto it = used_.find(offset);
  if (it == used_.end()) return false;
  std::uint64_t begin = offset, size = it->second;
  used_bytes_ -= size;
  used_.erase(it);
  // Coalesce with the free neighbours on both sides.
  auto next = free_.lower_bound(begin);
  if (next != free_.end() && next->first == begin + size) {
    size += next->second;
    next = free_.erase(next);
  }
  if (next != free_.begin()) {
    auto prev = std::prev(next);
    if (prev->first + prev->second == begin) {
      begin = prev->first;
      size += prev->second;
      free_.erase(prev);
    }
  }
  free_.emplace(begin, size);
  return true;
}

std::uint64_t RangeAllocator::largest_free_range() const {
  std::uint64_t largest = 0;
  for (const auto& [offset, size] : free_) largest = std::max(largest, size);
  return largest;
}

// ---- MemoryAllocator --------------------------------------------------------------------------

MemoryAllocator::MemoryAllocator(VkPhysicalDevice physical, VkDevice device, bool device_address,
                                 VkDeviceSize block_size)
    : device_(device), device_address_(device_address), block_size_(block_size) {
  vkGetPhysicalDeviceMemoryProperties(physical, &props_);
}

MemoryAllocator::~MemoryAllocator() {
  for (auto& pool : pools_)
    for (auto& block : pool.blocks)
      if (block.memory) vkFreeMemory(device_, block.memory, nullptr);
}

VkDeviceSize MemoryAllocator::largest_heap() const {
  VkDeviceSize largest = 0;
  for (std::uint32_t i = 0; i < props_.memoryHeapCount; ++i) largest = std::max(largest, props_.memoryHeaps[i].size);
  return largest;
}

std::uint32_t MemoryAllocator::choose_type(std::uint32_t type_bits, MemoryUse use, std::string_view object) const {
  VkMemoryPropertyFlags required = 0, preferred = 0;
  switch (use) {
    case MemoryUse::GpuOnly: preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT; break;
    // Coherent memory only, so the host never needs flush/invalidate calls.
    case MemoryUse::Upload:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      break;
    case MemoryUse::Readback:
      required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
      break;
  }
  for (const VkMemoryPropertyFlags want : {required | preferred, required}) {
    for (std::uint32_t i = 0; i < props_.memoryTypeCount; ++i)
      if ((type_bits & (1u << i)) && (props_.memoryTypes[i].propertyFlags & want) == want) return i;
  }
  throw Error(ErrorKind::OutOfMemory, object, "no Vulkan memory type fits the resource (type bits " +
                                                  std::to_string(type_bits) + ")");
}

VkDeviceMemory MemoryAllocator::allocate_memory(VkDeviceSize size, std::uint32_t type, std::string_view object,
                                                std::byte** mapped) {
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;  // buffers may need vkGetBufferDeviceAddress
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.pNext = device_address_ ? &flags : nullptr;
  info.allocationSize = size;
  info.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  const VkResult result = vkAllocateMemory(device_, &info, nullptr, &memory);
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw Error(ErrorKind::OutOfMemory, object,
                "vkAllocateMemory of " + std::to_string(size) + " bytes failed with " + std::string(result_name(result)));
  check(result, "vkAllocateMemory", object);
  *mapped = nullptr;
  if (props_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    void* pointer = nullptr;
    const VkResult map = vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &pointer);
    if (map != VK_SUCCESS) {
      vkFreeMemory(device_, memory, nullptr);
      check(map, "vkMapMemory", object);
    }
    *mapped = static_cast<std::byte*>(pointer);
  }
  device_memory_ += size;
  return memory;
}

Allocation MemoryAllocator::allocate(const VkMemoryRequirements& requirements, MemoryUse use, ResourceClass cls,
                                     std::string_view object) {
  const std::uint32_t type = choose_type(requirements.memoryTypeBits, use, object);
  const VkDeviceSize heap = props_.memoryHeaps[props_.memoryTypes[type].heapIndex].size;
  if (requirements.size > heap)
    throw Error(ErrorKind::OutOfMemory, object,
                "needs " + std::to_string(requirements.size) + " bytes but its memory heap holds only " +
                    std::to_string(heap));

  Allocation allocation;
  allocation.size = requirements.size;
  // Large resources get their own VkDeviceMemory: they would waste most of a block.
  if (requirements.size > block_size_ / 2) {
    allocation.memory = allocate_memory(requirements.size, type, object, &allocation.mapped);
    return allocation;
  }

  int pool_index = -1;
  for (std::size_t i = 0; i < pools_.size(); ++i)
    if (pools_[i].type == type && pools_[i].cls == cls) pool_index = static_cast<int>(i);
  if (pool_index < 0) {
    pools_.push_back(Pool{type, cls, {}});
    pool_index = static_cast<int>(pools_.size() - 1);
  }
  Pool& pool = pools_[static_cast<std::size_t>(pool_index)];
  const VkDeviceSize alignment = std::max<VkDeviceSize>(requirements.alignment, 1);
  for (std::uint32_t b = 0; b < pool.blocks.size(); ++b) {
    Block& block = pool.blocks[b];
    if (!block.memory) continue;
    if (const auto offset = block.ranges->allocate(requirements.size, alignment)) {
      allocation.memory = block.memory;
      allocation.offset = *offset;
      allocation.mapped = block.mapped ? block.mapped + *offset : nullptr;
      allocation.pool = pool_index;
      allocation.block = b;
      return allocation;
    }
  }
  // No room: a new block, in a freed slot when there is one.
  Block block;
  block.memory = allocate_memory(block_size_, type, object, &block.mapped);
  block.ranges = std::make_unique<RangeAllocator>(block_size_);
  std::uint32_t b = 0;
  while (b < pool.blocks.size() && pool.blocks[b].memory) ++b;
  if (b == pool.blocks.size())
    pool.blocks.push_back(std::move(block));
  else
    pool.blocks[b] = std::move(block);
  const auto offset = pool.blocks[b].ranges->allocate(requirements.size, alignment);
  allocation.memory = pool.blocks[b].memory;
  allocation.offset = offset.value_or(0);
  allocation.mapped = pool.blocks[b].mapped ? pool.blocks[b].mapped + allocation.offset : nullptr;
  allocation.pool = pool_index;
  allocation.block = b;
  return allocation;
}

void MemoryAllocator::free(const Allocation& allocation) {
  if (!allocation.memory) return;
  if (allocation.pool < 0) {
    vkFreeMemory(device_, allocation.memory, nullptr);
    device_memory_ -= allocation.size;
    return;
  }
  Pool& pool = pools_[static_cast<std::size_t>(allocation.pool)];
  Block& block = pool.blocks[allocation.block];
  block.ranges->free(allocation.offset);
  // Give an empty block back unless it is the pool's last one (avoids churn on create/destroy loops).
  std::size_t live = 0;
  for (const auto& other : pool.blocks) live += other.memory ? 1 : 0;
  if (block.ranges->empty() && live > 1) {
    vkFreeMemory(device_, block.memory, nullptr);
    device_memory_ -= block_size_;
    block = Block{};
  }
}

}  // namespace hal::vulkan
