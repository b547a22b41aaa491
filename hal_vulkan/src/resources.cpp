// Buffers and images: descriptor checks, format support, memory binding.
#include <string>

#include "check.hpp"
#include "device.hpp"

namespace hal::vulkan {
namespace {

VkImageUsageFlags to_vk(ImageUsage usage) {
  VkImageUsageFlags flags = 0;
  if (has(usage, ImageUsage::Sampled)) flags |= VK_IMAGE_USAGE_SAMPLED_BIT;
  if (has(usage, ImageUsage::Storage)) flags |= VK_IMAGE_USAGE_STORAGE_BIT;
  if (has(usage, ImageUsage::CopySrc)) flags |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  if (has(usage, ImageUsage::CopyDst)) flags |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  return flags;
}

VkFormatFeatureFlags2 needed_features(ImageUsage usage) {
  VkFormatFeatureFlags2 flags = 0;
  if (has(usage, ImageUsage::Sampled)) flags |= VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT;
  if (has(usage, ImageUsage::Storage)) flags |= VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT;
  if (has(usage, ImageUsage::CopySrc)) flags |= VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT;
  if (has(usage, ImageUsage::CopyDst)) flags |= VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT;
  return flags;
}

}  // namespace

VkFormat to_vk(Format format) {
  switch (format) {
    case Format::R8Unorm:
      return VK_FORMAT_R8_UNORM;
    case Format::RGBA8Unorm:
      return VK_FORMAT_R8G8B8A8_UNORM;
    case Format::R16F:
      return VK_FORMAT_R16_SFLOAT;
    case Format::RG16F:
      return VK_FORMAT_R16G16_SFLOAT;
    case Format::RGBA16F:
      return VK_FORMAT_R16G16B16A16_SFLOAT;
    case Format::R32F:
      return VK_FORMAT_R32_SFLOAT;
    case Format::RG32F:
      return VK_FORMAT_R32G32_SFLOAT;
    case Format::RGBA32F:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
    case Format::R32Uint:
      return VK_FORMAT_R32_UINT;
    case Format::RG32Uint:
      return VK_FORMAT_R32G32_UINT;
    case Format::RGBA32Uint:
      return VK_FORMAT_R32G32B32A32_UINT;
    case Format::RGBA16Uint:
      return VK_FORMAT_R16G16B16A16_UINT;
    case Format::Undefined:
      break;
  }
  return VK_FORMAT_UNDEFINED;
}

VkBufferUsageFlags to_vk(BufferUsage usage, bool device_address) {
  VkBufferUsageFlags flags = 0;
  if (has(usage, BufferUsage::Uniform)) flags |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
  if (has(usage, BufferUsage::Storage)) flags |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  if (has(usage, BufferUsage::CopySrc)) flags |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  if (has(usage, BufferUsage::CopyDst)) flags |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  if (has(usage, BufferUsage::AccelBuildInput) && device_address)
    flags |= VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
             VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  return flags;
}

BufferHandle VulkanDevice::create_buffer(const BufferDesc& desc) {
  check_alive();
  const Capabilities& caps = capabilities();
  // Check before asking the driver: larger requests are validation errors, not just failures.
  if (desc.size > allocator_->largest_heap())
    throw Error(ErrorKind::OutOfMemory, desc.name,
                "buffer of " + describe_bytes(desc.size) + " exceeds the largest memory heap (" +
                    describe_bytes(allocator_->largest_heap()) + ")");

  BufferObject object;
  object.name = desc.name;
  object.desc = desc;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = desc.size;
  info.usage = to_vk(desc.usage, caps.acceleration_structures);
  check_result(vkCreateBuffer(device_, &info, nullptr, &object.buffer), "vkCreateBuffer", desc.name);
  set_name(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(object.buffer), desc.name);
  try {
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, object.buffer, &requirements);
    object.memory = allocator_->allocate(requirements, MemoryUse::GpuOnly, ResourceClass::Buffer, desc.name);
    check_result(vkBindBufferMemory(device_, object.buffer, object.memory.memory, object.memory.offset),
                 "vkBindBufferMemory", desc.name);
  } catch (...) {
    vkDestroyBuffer(device_, object.buffer, nullptr);
    allocator_->free(object.memory);
    throw;
  }
  if (info.usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) {
    VkBufferDeviceAddressInfo address{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    address.buffer = object.buffer;
    object.address = vkGetBufferDeviceAddress(device_, &address);
  }
  return BufferHandle{buffers.add(std::move(object))};
}

ImageHandle VulkanDevice::create_image(const ImageDesc& desc) {
  check_alive();
  const VkFormat format = to_vk(desc.format);

  // Format support for every usage asked for, then the image-level limits of that combination.
  VkFormatProperties3 features3{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
  VkFormatProperties2 features{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2, &features3};
  vkGetPhysicalDeviceFormatProperties2(physical_, format, &features);
  const VkFormatFeatureFlags2 needed = needed_features(desc.usage);
  if ((features3.optimalTilingFeatures & needed) != needed)
    throw Error(ErrorKind::Unsupported, desc.name,
                "format " + std::string(format_name(desc.format)) + " does not support the requested usage on " +
                    adapter().name);
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = to_vk(desc.usage);
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImageFormatProperties limits;
  const VkResult supported =
      vkGetPhysicalDeviceImageFormatProperties(physical_, format, info.imageType, info.tiling, info.usage, 0, &limits);
  if (supported == VK_ERROR_FORMAT_NOT_SUPPORTED)
    throw Error(
        ErrorKind::Unsupported, desc.name,
        "format " + std::string(format_name(desc.format)) + " with this usage is not supported by " + adapter().name);
  check_result(supported, "vkGetPhysicalDeviceImageFormatProperties", desc.name);
  if (desc.width > limits.maxExtent.width || desc.height > limits.maxExtent.height)
    throw Error(ErrorKind::InvalidDescriptor, desc.name,
                "image size exceeds the largest extent of format " + std::string(format_name(desc.format)));

  ImageObject object;
  object.name = desc.name;
  object.desc = desc;
  object.format = format;
  check_result(vkCreateImage(device_, &info, nullptr, &object.image), "vkCreateImage", desc.name);
  set_name(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(object.image), desc.name);
  try {
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device_, object.image, &requirements);
    object.memory = allocator_->allocate(requirements, MemoryUse::GpuOnly, ResourceClass::Image, desc.name);
    check_result(vkBindImageMemory(device_, object.image, object.memory.memory, object.memory.offset),
                 "vkBindImageMemory", desc.name);
    // Views are only needed (and only valid) for shader usages.
    if (info.usage & (VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT)) {
      VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
      view.image = object.image;
      view.viewType = VK_IMAGE_VIEW_TYPE_2D;
      view.format = format;
      view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
      check_result(vkCreateImageView(device_, &view, nullptr, &object.view), "vkCreateImageView", desc.name);
      set_name(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<std::uint64_t>(object.view), desc.name);
    }
  } catch (...) {
    vkDestroyImage(device_, object.image, nullptr);
    allocator_->free(object.memory);
    throw;
  }
  return ImageHandle{images.add(std::move(object))};
}

}  // namespace hal::vulkan
