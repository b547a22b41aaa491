// hal_vulkan/vulkan.hpp: the Vulkan implementation of the HAL. The only public entry points are
// here; nothing outside hal_vulkan includes a Vulkan header.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hal/device.hpp"

namespace hal::vulkan {

// One physical device as the Vulkan driver reports it, with the HAL capabilities it would have.
struct AdapterReport {
  std::uint32_t index = 0;  // position in enumeration order, usable as DeviceOptions::adapter
  AdapterInfo info;
  Capabilities capabilities;
};

// Lists every Vulkan physical device. Throws hal::Error(NoDevice) when there is no Vulkan loader,
// no driver, or no device, with a message saying which.
std::vector<AdapterReport> list_adapters();

// Environment variable naming the adapter when DeviceOptions::adapter is empty.
inline constexpr const char* kAdapterEnvVar = "ASVGF_DEVICE";

}  // namespace hal::vulkan
