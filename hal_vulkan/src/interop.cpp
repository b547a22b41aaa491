// The HAL on the caller's Vulkan objects (hal_vulkan/interop.hpp): a device that borrows the
// instance, device and queue, imported images, and command lists over the caller's command buffer.
#include "hal_vulkan/interop.hpp"

#include <string>

#include "check.hpp"
#include "command_list.hpp"
#include "device.hpp"

namespace hal::vulkan {
namespace {

VulkanDevice& vulkan_device(hal::Device& device, std::string_view what) {
  auto* vk = dynamic_cast<VulkanDevice*>(&device);
  if (!vk)
    throw Error(ErrorKind::InvalidUsage, what,
                "the device is not a Vulkan HAL device (wrap_device's or create_device's, without another layer)");
  return *vk;
}

Format from_vk(VkFormat format) {
  for (const Format f : kAllFormats)
    if (to_vk(f) == format) return f;
  return Format::Undefined;
}

}  // namespace

VulkanDevice::VulkanDevice(const ExternalDevice& external) : owns_device_(false) {
  if (!external.instance || !external.physical || !external.device || !external.queue)
    throw Error(ErrorKind::InvalidDescriptor, "external Vulkan device",
                "instance, physical device, device and queue must all be given");
  instance_ = std::make_unique<Instance>(external.instance, external.debug_utils);
  physical_ = external.physical;
  adapter_ = describe_adapter(physical_, 0);
  read_limits();
  std::uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, families.data());
  if (external.queue_family >= family_count || !(families[external.queue_family].queueFlags & VK_QUEUE_COMPUTE_BIT))
    throw Error(ErrorKind::Unsupported, adapter_.info.name,
                "queue family " + std::to_string(external.queue_family) + " does not exist or has no compute");
  device_ = external.device;
  queue_ = external.queue;
  queue_family_ = external.queue_family;
  timestamp_bits_ = families[queue_family_].timestampValidBits;
  Capabilities& caps = adapter_.capabilities;
  caps.timestamps = timestamp_bits_ > 0 && limits_.timestampPeriod > 0.0f;
  // What the caller enabled, not what the adapter could do.
  caps.acceleration_structures = external.acceleration_structures;
  caps.ray_query = external.acceleration_structures && external.ray_query;
  caps.fp16_storage = false;
  load_functions();
  try {
    create_shared_objects();
  } catch (...) {
    // No destructor runs for a failed constructor: release what was made on the caller's device.
    if (ring_.buffer) vkDestroyBuffer(device_, ring_.buffer, nullptr);
    if (allocator_) allocator_->free(ring_.memory);
    if (transfer_pool_) vkDestroyCommandPool(device_, transfer_pool_, nullptr);
    throw;
  }
}

ImageHandle VulkanDevice::import_image(VkImage image, VkFormat format, std::uint32_t width, std::uint32_t height,
                                       ImageUsage usage, std::string_view name) {
  check_alive();
  const std::string text(name);
  if (!image) throw Error(ErrorKind::InvalidDescriptor, text, "the image to import is VK_NULL_HANDLE");
  const Format hal_format = from_vk(format);
  if (hal_format == Format::Undefined)
    throw Error(ErrorKind::Unsupported, text,
                "VkFormat " + std::to_string(static_cast<int>(format)) + " has no hal::Format (RGBA32F, RGBA16F, ...)");
  if (width == 0 || height == 0 || width > adapter_.capabilities.max_image_dimension ||
      height > adapter_.capabilities.max_image_dimension)
    throw Error(ErrorKind::InvalidDescriptor, text, "size " + std::to_string(width) + "x" + std::to_string(height));
  ImageObject object;
  object.name = text;
  object.desc = {text, width, height, hal_format, usage};
  object.format = format;
  object.image = image;
  object.owned = false;
  if (has(usage, ImageUsage::Sampled) || has(usage, ImageUsage::Storage)) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    check_result(vkCreateImageView(device_, &view, nullptr, &object.view), "vkCreateImageView", text);
    set_name(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<std::uint64_t>(object.view), text);
  }
  return ImageHandle{images.add(std::move(object))};
}

std::unique_ptr<hal::Device> wrap_device(const ExternalDevice& external) {
  return std::make_unique<VulkanDevice>(external);
}

hal::ImageHandle import_image(hal::Device& device, VkImage image, VkFormat format, std::uint32_t width,
                              std::uint32_t height, hal::ImageUsage usage, std::string_view name) {
  return vulkan_device(device, name).import_image(image, format, width, height, usage, name);
}

std::unique_ptr<hal::CommandList> wrap_command_buffer(hal::Device& device, VkCommandBuffer command_buffer,
                                                      std::string_view name) {
  return std::make_unique<VulkanCommandList>(vulkan_device(device, name), std::string(name), command_buffer);
}

}  // namespace hal::vulkan
