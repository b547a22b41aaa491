// `asvgf info`: what each backend finds: Vulkan devices, the OpenGL and OpenGL ES contexts, with
// drivers, API versions and capabilities.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "hal/error.hpp"
#include "hal_gl/gl.hpp"
#include "hal_vulkan/vulkan.hpp"

namespace asvgf::cli {
namespace {

const char* yes_no(bool v) {
  return v ? "yes" : "no";
}

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
  for (const auto flavour : {hal::gl::Flavour::Gl, hal::gl::Flavour::Gles}) {
    const char* name = flavour == hal::gl::Flavour::Gl ? "gl" : "gles";
    try {
      hal::gl::DeviceOptions gl_options;
      gl_options.flavour = flavour;
      const auto gl = hal::gl::create_device(gl_options);
      const auto& g = gl->capabilities();
      std::printf("\nbackend %s: %s, %s\n", name, gl->adapter().name.c_str(), gl->adapter().api_version.c_str());
      std::printf(
          "  timestamps %s, max image dimension %u, largest storage binding %llu bytes, tracing variant "
          "software BVH (no acceleration structures)\n",
          yes_no(g.timestamps), g.max_image_dimension, static_cast<unsigned long long>(g.max_storage_buffer_range));
    } catch (const hal::Error& e) {
      std::printf("\nbackend %s: not available: %s\n", name, e.what());
    }
  }
  return 0;
}

}  // namespace

std::function<int()> add_info_command(CLI::App& app) {
  auto device = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand(
      "info", "List the Vulkan devices and the OpenGL / ES contexts with their drivers, versions and capabilities");
  cmd->add_option("--device", *device,
                  "Adapter to open: index or part of its name (default: $ASVGF_DEVICE, else best)");
  return [device] { return run_info(*device); };
}

}  // namespace asvgf::cli
