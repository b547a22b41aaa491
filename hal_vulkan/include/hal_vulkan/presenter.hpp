// hal_vulkan/presenter.hpp: showing HAL images in a GLFW window (link target hal_vulkan_present).
//
// Usage: glfwInit(); create the window with GLFW_CLIENT_API = GLFW_NO_API; create the device with
// DeviceOptions::instance_extensions = glfw_instance_extensions(); then per frame, after a barrier
// that puts the image in hal::State::Present, call present(image). The headless path (everything
// in vulkan.hpp) never needs this header or a window system.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hal/device.hpp"

struct GLFWwindow;

namespace hal::vulkan {

// The instance extensions GLFW needs for window surfaces (glfwInit must have succeeded).
// Throws Unsupported when GLFW finds no Vulkan support.
std::vector<std::string> glfw_instance_extensions();

class Presenter {
 public:
  // `device` must come from create_device with glfw_instance_extensions(). Throws Unsupported
  // when the device's queue cannot present to the window's surface.
  Presenter(hal::Device& device, GLFWwindow* window, bool vsync = true);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  // Scales `image` (in State::Present, created with CopySrc usage, a float or unorm format) to the
  // window with a linear blit and presents it. The swapchain is recreated when the window's size
  // changes or the surface reports it out of date. Returns false (nothing shown) while the window
  // has zero size (minimized).
  bool present(hal::ImageHandle image);

  // Current swapchain size in pixels ({0, 0} before the first present or while minimized).
  std::pair<std::uint32_t, std::uint32_t> extent() const;
  // How many times the swapchain was (re)created.
  std::uint32_t swapchain_generation() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace hal::vulkan
