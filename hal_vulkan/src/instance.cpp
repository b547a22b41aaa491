#include "instance.hpp"

#include <cstdio>
#include <cstring>

#include "check.hpp"

namespace hal::vulkan {
namespace {

bool has_layer(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

bool has_instance_extension(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> props(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, props.data());
  for (const auto& p : props)
    if (std::strcmp(p.extensionName, name) == 0) return true;
  return false;
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

}  // namespace

Instance::Instance(const InstanceOptions& options) : on_message_(options.on_message) {
  std::uint32_t loader_version = 0;
  if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS || loader_version < VK_API_VERSION_1_3)
    throw Error(ErrorKind::NoDevice, "Vulkan loader", "Vulkan 1.3 is required; the installed loader is older");

  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  for (const auto& e : options.extensions) {
    if (!has_instance_extension(e.c_str()))
      throw Error(ErrorKind::Unsupported, e, "the Vulkan instance extension was asked for but the loader lacks it");
    if (e != VK_EXT_DEBUG_UTILS_EXTENSION_NAME) extensions.push_back(e.c_str());
  }
  if (options.validation) {
    if (!has_layer(kValidationLayer))
      throw Error(ErrorKind::Unsupported, kValidationLayer,
                  "validation was asked for but the layer is not installed (Debian package vulkan-validationlayers)");
    layers.push_back(kValidationLayer);
  }
  // Debug utils give object names and command labels in validation messages and captures.
  debug_utils_ = options.validation || has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (debug_utils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "asvgf";
  app.pEngineName = "asvgf";
  app.apiVersion = VK_API_VERSION_1_3;

  // Synchronization validation is off by default in the layer; ask for it explicitly.
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;

  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &Instance::on_debug;
  messenger.pUserData = this;
  if (options.validation) {
    features.pNext = &messenger;
  }

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = options.validation ? &features : nullptr;
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  const VkResult result = vkCreateInstance(&info, nullptr, &instance_);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw Error(ErrorKind::NoDevice, "Vulkan instance",
                "no Vulkan driver is installed (on Debian: mesa-vulkan-drivers gives lavapipe)");
  check(result, "vkCreateInstance", "Vulkan instance");

  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create) check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT", "Vulkan instance");
  }
}

Instance::~Instance() {
  if (!owned_) return;
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::vector<VkPhysicalDevice> Instance::physical_devices() const {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices", "Vulkan instance");
  if (count == 0)
    throw Error(ErrorKind::NoDevice, "Vulkan instance",
                "the Vulkan loader found no device: is a driver installed (mesa-vulkan-drivers) and "
                "VK_ICD_FILENAMES / VK_DRIVER_FILES unset or correct?");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices", "Vulkan instance");
  return devices;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Instance::on_debug(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                  VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                  const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  const auto* self = static_cast<const Instance*>(user);
  std::string message = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "validation error: "
                                                                                    : "validation warning: ";
  message += data && data->pMessage ? data->pMessage : "(no message)";
  if (self && self->on_message_)
    self->on_message_(message);
  else
    std::fprintf(stderr, "%s\n", message.c_str());
  return VK_FALSE;
}

std::vector<std::string> device_extensions(VkPhysicalDevice physical) {
  std::uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> props(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, props.data());
  std::vector<std::string> names;
  names.reserve(count);
  for (const auto& p : props) names.emplace_back(p.extensionName);
  return names;
}

}  // namespace hal::vulkan
