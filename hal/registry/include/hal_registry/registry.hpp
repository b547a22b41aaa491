// hal_registry/registry.hpp: the one list of the HAL backends this build has. Each backend
// registers itself in its own folder (hal_<name>/src/backend_entry.cpp, named in its CMakeLists
// with asvgf_register_backend): its names, how it opens a device and how it presents. `--backend`,
// ASVGF_BACKEND, `asvgf info`, the demo and the test suites choose backends here and nowhere else.
// Part of this repository's tools and tests, not of the installed package.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hal/device.hpp"

namespace hal::registry {

// How a backend shows an image in a window; the demo makes its window and presenter by it.
enum class Presentation {
  VulkanSurface,    // a Vulkan surface and swapchain (hal::vulkan::Presenter)
  OpenGlContext,    // the window's OpenGL 4.5 core context, adopted by the device (hal::gl::present)
  OpenGlEsContext,  // the same with an OpenGL ES 3.1 context
};

struct OpenOptions {
  std::string adapter;      // backends with several adapters: index or part of the name ("" = best)
  bool validation = false;  // the API's validation layer, where it has one (OpenGL's debug output is always on)
  std::function<void(const std::string&)> on_message;  // validation / debug messages; stderr when empty
  std::function<void()> make_current;                  // OpenGL: adopt the calling thread's (a window's) context
  std::vector<std::string> instance_extensions;        // Vulkan: what a window surface needs (GLFW's list)
};

// One adapter a backend can open, for `asvgf info`.
struct AdapterListing {
  std::uint32_t index = 0;
  AdapterInfo info;
  Capabilities capabilities;
};

struct Backend {
  std::string name;         // what --backend and ASVGF_BACKEND take
  std::string description;  // one line, for --help and `asvgf info`
  Presentation presentation = Presentation::VulkanSurface;
  bool adapters_selectable = false;                                 // OpenOptions::adapter means something (--device)
  std::function<std::unique_ptr<Device>(const OpenOptions&)> open;  // throws hal::Error (NoDevice, ...)
  // Every adapter the backend sees (empty function: the backend has one, what open() gives).
  std::function<std::vector<AdapterListing>()> list_adapters;
  // What is wrong with the environment variables the backend reads, naming the variable and its
  // valid values; "" when nothing is (empty function: it reads none). open() refuses the same with
  // hal::Error(InvalidUsage); the tools ask first, to report it as bad input.
  std::function<std::string()> environment_problem;
};

// Every backend of this build, the default first.
const std::vector<Backend>& backends();
// The backend named `name`; throws hal::Error(InvalidUsage) naming it and listing the names.
const Backend& backend(std::string_view name);
// The first backend: what runs when nothing is chosen.
const Backend& default_backend();
// The names, in order, joined by `separator` ("vulkan, gl, gles").
std::string names(std::string_view separator = ", ");

}  // namespace hal::registry
