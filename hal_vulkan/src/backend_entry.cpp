// The Vulkan backend's entry in the registry (hal_registry/registry.hpp).
#include "hal_registry/registry.hpp"
#include "hal_vulkan/vulkan.hpp"

namespace hal::registry {

std::vector<Backend> hal_vulkan_backends() {
  Backend vulkan;
  vulkan.name = "vulkan";
  vulkan.description = "Vulkan 1.3 (ray queries where the driver has them, else the software BVH)";
  vulkan.presentation = Presentation::VulkanSurface;
  vulkan.adapters_selectable = true;
  vulkan.open = [](const OpenOptions& o) {
    hal::vulkan::DeviceOptions options;
    options.adapter = o.adapter;
    options.validation = o.validation;
    options.on_validation_message = o.on_message;
    options.instance_extensions = o.instance_extensions;
    return hal::vulkan::create_device(options);
  };
  vulkan.list_adapters = [] {
    std::vector<AdapterListing> out;
    for (const auto& a : hal::vulkan::list_adapters()) out.push_back({a.index, a.info, a.capabilities});
    return out;
  };
  return {vulkan};
}

}  // namespace hal::registry
