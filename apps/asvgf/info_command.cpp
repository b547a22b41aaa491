// `asvgf info`: what each backend of the registry finds: its adapters (Vulkan's devices) and the
// device it opens (the OpenGL and OpenGL ES contexts), with drivers, API versions and capabilities.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "hal/error.hpp"
#include "hal_registry/registry.hpp"

namespace asvgf::cli {
namespace {

const char* yes_no(bool v) {
  return v ? "yes" : "no";
}

void print_capabilities(const hal::Capabilities& c) {
  std::printf("  ray queries:              %s\n", yes_no(c.ray_query));
  std::printf("  acceleration structures:  %s\n", yes_no(c.acceleration_structures));
  std::printf("  timestamps:               %s\n", yes_no(c.timestamps));
  std::printf("  fp16 storage:             %s\n", yes_no(c.fp16_storage));
  std::printf("  subgroup size:            %u\n", c.subgroup_size);
  std::printf("  max image dimension:      %u\n", c.max_image_dimension);
  std::printf("  largest storage binding:  %llu bytes\n", static_cast<unsigned long long>(c.max_storage_buffer_range));
  std::printf("  tracing variant:          %s\n", c.ray_query ? "ray queries" : "software BVH");
}

// Every backend of the registry: the adapters it lists (where it has a choice) and the device it
// opens, with what was actually enabled. A backend that cannot open says why and the rest go on.
int run_info(const std::string& device) {
  int opened = 0;
  bool first = true;
  for (const auto& backend : hal::registry::backends()) {
    std::printf("%sbackend %s: %s\n", first ? "" : "\n", backend.name.c_str(), backend.description.c_str());
    first = false;
    try {
      if (backend.list_adapters) {
        const auto adapters = backend.list_adapters();
        std::printf("  adapters: %zu\n", adapters.size());
        for (const auto& a : adapters) {
          std::printf("\n  [%u] %s\n", a.index, a.info.name.c_str());
          std::printf("  type:                     %s\n", std::string(hal::to_string(a.info.type)).c_str());
          std::printf("  driver:                   %s\n", a.info.driver.c_str());
          std::printf("  API version:              %s\n", a.info.api_version.c_str());
          print_capabilities(a.capabilities);
        }
      }
      hal::registry::OpenOptions options;
      options.adapter = device;
      const auto created = backend.open(options);
      std::printf("\n  opened: %s, %s (%s%s)\n", created->adapter().name.c_str(),
                  created->adapter().api_version.c_str(),
                  !backend.adapters_selectable ? "its one context"
                  : device.empty()             ? "default choice"
                                               : "--device ",
                  backend.adapters_selectable ? device.c_str() : "");
      print_capabilities(created->capabilities());
      ++opened;
    } catch (const hal::Error& e) {
      std::printf("  not available: %s\n", e.what());
    }
  }
  if (opened == 0) {
    std::fprintf(stderr, "asvgf info: no backend could open a device (%s)\n", hal::registry::names().c_str());
    return 1;
  }
  return 0;
}

}  // namespace

std::function<int()> add_info_command(CLI::App& app) {
  auto device = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand(
      "info",
      "List what every backend finds (Vulkan devices, the OpenGL / ES contexts) with drivers, versions and "
      "capabilities");
  cmd->add_option("--device", *device,
                  "Adapter to open: index or part of its name (default: $ASVGF_DEVICE, else best)");
  return [device] { return run_info(*device); };
}

}  // namespace asvgf::cli
