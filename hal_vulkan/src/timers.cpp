// GPU timers: one timestamp pair per region; milliseconds from timestampPeriod with the queue's
// valid bits masked. Without timestamps every region reads as "no time" rather than zero.
#include <cmath>
#include <string>

#include "check.hpp"
#include "command_list.hpp"
#include "device.hpp"

namespace hal::vulkan {

TimerQueriesHandle VulkanDevice::create_timer_queries(const TimerQueriesDesc& desc) {
  check_alive();
  TimerObject object;
  object.name = desc.name;
  object.regions = desc.regions;
  object.submitted.assign(desc.regions, false);
  if (capabilities().timestamps) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = desc.regions * 2;
    check_result(vkCreateQueryPool(device_, &info, nullptr, &object.pool), "vkCreateQueryPool", desc.name);
    set_name(VK_OBJECT_TYPE_QUERY_POOL, reinterpret_cast<std::uint64_t>(object.pool), desc.name);
    // Queries start undefined; reset them once so that reading an unused region is valid.
    try {
      run_now(desc.name, [&](VkCommandBuffer cmd) { vkCmdResetQueryPool(cmd, object.pool, 0, info.queryCount); });
    } catch (...) {
      vkDestroyQueryPool(device_, object.pool, nullptr);
      throw;
    }
  }
  return TimerQueriesHandle{timers.add(std::move(object))};
}

std::vector<std::optional<double>> VulkanDevice::read_timers(TimerQueriesHandle handle) {
  check_alive();
  TimerObject& t = timers.get(handle.id, "timer queries");
  std::vector<std::optional<double>> times(t.regions);
  if (!t.pool) return times;
  const std::uint64_t mask = timestamp_bits_ >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << timestamp_bits_) - 1;
  for (std::uint32_t r = 0; r < t.regions; ++r) {
    if (!t.submitted[r]) continue;
    std::uint64_t values[4] = {};  // begin, available, end, available
    const VkResult result =
        vkGetQueryPoolResults(device_, t.pool, 2 * r, 2, sizeof values, values, 2 * sizeof(std::uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (result == VK_NOT_READY) continue;
    check_result(result, "vkGetQueryPoolResults", t.name);
    if (!values[1] || !values[3]) continue;
    const std::uint64_t ticks = (values[2] - values[0]) & mask;  // wraps correctly within the valid bits
    const double ms = static_cast<double>(ticks) * static_cast<double>(limits_.timestampPeriod) * 1e-6;
    if (std::isfinite(ms)) times[r] = ms;
  }
  return times;
}

TimerObject& VulkanCommandList::timer_region(TimerQueriesHandle handle, std::uint32_t region) {
  (void)region;  // hal::validate checked it is within the queries
  return device_.timers.get(handle.id, "timer queries");
}

void VulkanCommandList::begin_timer(TimerQueriesHandle handle, std::uint32_t region) {
  VkCommandBuffer cmd = recording();
  TimerObject& t = timer_region(handle, region);
  if (!t.pool) return;
  vkCmdResetQueryPool(cmd, t.pool, 2 * region, 2);
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, t.pool, 2 * region);
}

void VulkanCommandList::end_timer(TimerQueriesHandle handle, std::uint32_t region) {
  VkCommandBuffer cmd = recording();
  TimerObject& t = timer_region(handle, region);
  if (!t.pool) return;
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, t.pool, 2 * region + 1);
  timer_writes_.emplace_back(handle.id, region);
}

}  // namespace hal::vulkan
