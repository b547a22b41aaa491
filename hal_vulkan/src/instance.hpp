// The Vulkan instance: loader checks, validation layer and debug messenger, device enumeration.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <string>
#include <vector>

#include "hal_vulkan/vulkan.hpp"

namespace hal::vulkan {

struct InstanceOptions {
  // Enables VK_LAYER_KHRONOS_validation with synchronization validation; throws Unsupported when
  // the layer is not installed.
  bool validation = false;
  // Instance extensions a window system needs (from glfwGetRequiredInstanceExtensions).
  std::vector<std::string> extensions;
  // Receives every validation message (warnings and errors); default prints to stderr.
  std::function<void(const std::string&)> on_message;
};

class Instance {
 public:
  explicit Instance(const InstanceOptions& options);
  // Someone else's instance (interop): used, never destroyed.
  Instance(VkInstance borrowed, bool debug_utils) : instance_(borrowed), debug_utils_(debug_utils), owned_(false) {}
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  VkInstance handle() const { return instance_; }
  std::vector<VkPhysicalDevice> physical_devices() const;
  bool debug_utils() const { return debug_utils_; }

 private:
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  bool debug_utils_ = false;
  bool owned_ = true;
  std::function<void(const std::string&)> on_message_;
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_debug(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data, void* user);
};

std::vector<std::string> device_extensions(VkPhysicalDevice physical);
AdapterReport describe_adapter(VkPhysicalDevice physical, std::uint32_t index);

}  // namespace hal::vulkan
