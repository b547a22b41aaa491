// hal_vulkan/interop.hpp: the HAL on Vulkan objects your renderer already has, so that a renderer
// with its own VkDevice does not need a second one. The one public header of hal_vulkan that
// includes Vulkan's.
//
//   auto device = hal::vulkan::wrap_device({instance, physical, vk_device, queue, family});
//   hal::ImageHandle color = hal::vulkan::import_image(*device, vk_image, VK_FORMAT_R16G16B16A16_SFLOAT,
//                                                      width, height, hal::ImageUsage::Sampled, "color");
//   auto commands = hal::vulkan::wrap_command_buffer(*device, vk_command_buffer, "denoise");
//   ... record HAL work (e.g. asvgf::Denoiser::record) into *commands, then end and submit
//   vk_command_buffer yourself.
//
// Layouts: the HAL keeps every image a shader uses in VK_IMAGE_LAYOUT_GENERAL. An image you hand
// over must be in GENERAL with your writes made visible to compute shaders (pass State::ShaderWrite,
// or ShaderRead if you only read it), or in TRANSFER_SRC/DST_OPTIMAL (CopySrc/CopyDst), or its
// contents may be discarded (Undefined). The HAL records the barriers from there, and leaves each
// image in the state it reports (the denoiser: inputs ShaderRead, outputs the state you ask for).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string_view>

#include "hal/command_list.hpp"
#include "hal/device.hpp"

namespace hal::vulkan {

// Your Vulkan objects. The HAL never destroys them; destroy the HAL device (and everything created
// on it) before them.
struct ExternalDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;  // created with Vulkan 1.3 and the synchronization2 feature
  VkQueue queue = VK_NULL_HANDLE;    // the HAL's own submissions (host transfers, submit()) go here
  std::uint32_t queue_family = 0;    // with compute; command buffers you wrap come from this family
  // What `device` was created with (a VkDevice cannot be asked): acceleration structures need
  // VK_KHR_acceleration_structure, VK_KHR_deferred_host_operations and bufferDeviceAddress; ray
  // queries also VK_KHR_ray_query with rayQuery. The denoiser needs neither.
  bool acceleration_structures = false;
  bool ray_query = false;
  bool debug_utils = false;  // VK_EXT_debug_utils is enabled on `instance`: labels and object names
};

// A hal::Device on your device. Throws hal::Error: InvalidDescriptor (a null handle), Unsupported
// (the physical device is older than Vulkan 1.3, or the queue family has no compute).
std::unique_ptr<hal::Device> wrap_device(const ExternalDevice& external);

// Your image as a HAL image of `device` (made by wrap_device): 2D, one mip level and layer, of the
// VkFormat matching a hal::Format (e.g. VK_FORMAT_R32G32B32A32_SFLOAT is RGBA32F), created with at
// least the VkImageUsageFlags that `usage` names. destroy() releases only the HAL's view of it.
// Import each image once and keep the handle: the denoiser caches descriptor sets per handle
// (handles are never reused), so importing anew every frame grows that cache frame by frame.
// Throws hal::Error: InvalidUsage (not a wrapped Vulkan device), Unsupported (a format the HAL has
// no hal::Format for).
hal::ImageHandle import_image(hal::Device& device, VkImage image, VkFormat format, std::uint32_t width,
                              std::uint32_t height, hal::ImageUsage usage, std::string_view name);

// A HAL command list that records into your primary command buffer, which must be in the
// recording state (begun) and from ExternalDevice::queue_family. You end and submit it, on
// ExternalDevice::queue: the HAL's wait() (which the denoiser's destructor, input_report() and
// sanitised() use) waits on that queue only. The HAL's submit() refuses it. Uniform data it records
// lives in the device's upload ring until reset(): call reset() (or destroy the list) only once
// the GPU has finished that submission. Recording leaves the HAL's pipeline and descriptor sets
// bound: bind your own again for compute work you record after it. GPU timings are not available
// for work recorded this way (the HAL does not see the submission).
std::unique_ptr<hal::CommandList> wrap_command_buffer(hal::Device& device, VkCommandBuffer command_buffer,
                                                      std::string_view name);

}  // namespace hal::vulkan
