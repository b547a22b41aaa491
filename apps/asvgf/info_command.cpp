// `asvgf info`: what the Vulkan backend finds: devices, drivers, API versions and capabilities.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "hal_vulkan/vulkan.hpp"

namespace asvgf::cli {
namespace {

const char* yes_no(bool v) { return v ? "yes" : "no"; }

int run_info(const std::string& device) {
  const auto adapters = hal::vulkan::list_adapters();  // throws NoDevice with a clear message
  std::printf("Vulkan devices: %zu\n", adapters.size());
  for (const auto& a : adapters) {
    const auto& c = a.capabilities;
    std::printf("\n[%u] %s\n", a.index, a.info.name.c_str());
    std::printf("  type:                     %s\n", std::string(hal::to_string(a.info.type)).c_str());
    std::printf("  driver:                   %s\n", a.info.driver.c_str());
    std::printf("  API version:              %s\n", a.info.api_version.c_str());
    std::printf("  ray queries:              %s\n", yes_no(c.ray_query));
    std::printf("  acceleration structures:  %s\n", yes_no(c.acceleration_structures));
    std::printf("  timestamps:               %s\n", yes_no(c.timestamps));
    std::printf("  fp16 storage:             %s\n", yes_no(c.fp16_storage));
    std::printf("  subgroup size:            %u\n", c.subgroup_size);
    std::printf("  max image dimension:      %u\n", c.max_image_dimension);
    std::printf("  tracing variant:          %s\n", c.ray_query ? "ray queries" : "software BVH");
  }
  // The device the renderer would use, created: what was actually enabled.
  hal::vulkan::DeviceOptions options;
  options.adapter = device;
  const auto created = hal::vulkan::create_device(options);
  const auto& c = created->capabilities();
  std::printf("\nselected: %s (%s%s)\n", created->adapter().name.c_str(),
              device.empty() ? "default choice" : "--device ", device.c_str());
  std::printf("  enabled: ray queries %s, acceleration structures %s, timestamps %s, fp16 storage %s\n",
              yes_no(c.ray_query), yes_no(c.acceleration_structures), yes_no(c.timestamps), yes_no(c.fp16_storage));
  return 0;
}

}  // namespace

std::function<int()> add_info_command(CLI::App& app) {
  auto device = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("info", "List Vulkan devices with their driver, API version and capabilities");
  cmd->add_option("--device", *device, "Adapter to open: index or part of its name (default: $ASVGF_DEVICE, else best)");
  return [device] { return run_info(*device); };
}

}  // namespace asvgf::cli
