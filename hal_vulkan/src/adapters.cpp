// Enumerating Vulkan physical devices and reading what each one supports.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "hal/error.hpp"
#include "hal_vulkan/vulkan.hpp"
#include "instance.hpp"

namespace hal::vulkan {
namespace {

std::string version_string(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

DeviceType device_type(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return DeviceType::IntegratedGpu;
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return DeviceType::DiscreteGpu;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return DeviceType::VirtualGpu;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return DeviceType::Cpu;
    default: return DeviceType::Other;
  }
}

}  // namespace

AdapterReport describe_adapter(VkPhysicalDevice physical, std::uint32_t index) {
  VkPhysicalDeviceMaintenance4Properties maintenance4{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_PROPERTIES};
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties basic{};
  vkGetPhysicalDeviceProperties(physical, &basic);
  // Maintenance4 properties exist only on Vulkan 1.3 devices (or with the extension).
  if (basic.apiVersion >= VK_API_VERSION_1_3) driver.pNext = &maintenance4;
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES, &driver};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(physical, &props);

  VkPhysicalDeviceRayQueryFeaturesKHR ray_query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR accel{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDevice16BitStorageFeatures storage16{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_16BIT_STORAGE_FEATURES};
  const auto extensions = device_extensions(physical);
  auto has_ext = [&](const char* name) {
    for (const auto& e : extensions)
      if (e == name) return true;
    return false;
  };
  // Only chain feature structs of extensions the device has (the spec requires it).
  void* chain = &storage16;
  if (has_ext(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME)) {
    accel.pNext = chain;
    chain = &accel;
  }
  if (has_ext(VK_KHR_RAY_QUERY_EXTENSION_NAME)) {
    ray_query.pNext = chain;
    chain = &ray_query;
  }
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, chain};
  vkGetPhysicalDeviceFeatures2(physical, &features);

  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &family_count, families.data());
  bool compute_timestamps = false;
  for (const auto& f : families)
    if ((f.queueFlags & VK_QUEUE_COMPUTE_BIT) && f.timestampValidBits > 0) compute_timestamps = true;

  const VkPhysicalDeviceProperties& p = props.properties;
  AdapterReport report;
  report.index = index;
  report.info.name = p.deviceName;
  report.info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  report.info.api_version = "Vulkan " + version_string(p.apiVersion);
  report.info.type = device_type(p.deviceType);

  Capabilities& caps = report.capabilities;
  caps.acceleration_structures = has_ext(VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
                                 accel.accelerationStructure == VK_TRUE;
  caps.ray_query = caps.acceleration_structures && has_ext(VK_KHR_RAY_QUERY_EXTENSION_NAME) &&
                   ray_query.rayQuery == VK_TRUE;
  caps.fp16_storage = storage16.storageBuffer16BitAccess == VK_TRUE;
  caps.timestamps = compute_timestamps && p.limits.timestampPeriod > 0.0f;
  caps.subgroup_size = subgroup.subgroupSize;
  caps.max_image_dimension = p.limits.maxImageDimension2D;
  caps.max_storage_buffer_range = p.limits.maxStorageBufferRange;
  caps.max_buffer_size = maintenance4.maxBufferSize ? maintenance4.maxBufferSize : p.limits.maxStorageBufferRange;
  return report;
}

std::vector<AdapterReport> list_adapters() {
  Instance instance(InstanceOptions{});
  std::vector<AdapterReport> reports;
  const auto physicals = instance.physical_devices();
  for (std::uint32_t i = 0; i < physicals.size(); ++i) reports.push_back(describe_adapter(physicals[i], i));
  return reports;
}

}  // namespace hal::vulkan
