// hal_vulkan/vulkan.hpp: the Vulkan implementation of the HAL. The only public entry points are
// here; nothing outside hal_vulkan includes a Vulkan header.
#pragma once

#include <functional>
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

struct DeviceOptions {
  // Which adapter: its index in list_adapters() order, or a case-insensitive substring of its name
  // ("llvmpipe", "h200"). Empty: the ASVGF_DEVICE environment variable, and when that is unset too,
  // the first discrete GPU, else integrated, virtual, CPU (lavapipe) in that order.
  std::string adapter;
  // VK_LAYER_KHRONOS_validation with synchronization validation; messages go to
  // on_validation_message (stderr when it is empty).
  bool validation = false;
  std::function<void(const std::string&)> on_validation_message;
  // Fail with Unsupported when the chosen adapter has no ray queries (otherwise a device without
  // them is created and capabilities().ray_query is false).
  bool require_ray_query = false;
  // Extra instance extensions, e.g. from glfwGetRequiredInstanceExtensions; asking for
  // VK_KHR_surface also enables VK_KHR_swapchain on the device.
  std::vector<std::string> instance_extensions;
};

// Index of the adapter `wanted` selects among `adapters` (the rules of DeviceOptions::adapter; an
// empty `wanted` picks by device type). Throws NoDevice naming `wanted` and listing the adapters.
std::uint32_t select_adapter(const std::vector<AdapterReport>& adapters, const std::string& wanted);

// Creates a Vulkan device. Command lists it creates must be destroyed before it. Uniform data and
// TLAS instances recorded into command lists live in a 32 MiB per-device upload ring until the
// list is reset or destroyed after wait(). Throws hal::Error: NoDevice (no driver, or no adapter matches),
// Unsupported (Vulkan 1.3 missing, validation layer or required ray queries missing).
std::unique_ptr<hal::Device> create_device(const DeviceOptions& options = {});

}  // namespace hal::vulkan
