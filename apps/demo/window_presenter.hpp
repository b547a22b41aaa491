// demo/window_presenter.hpp: shows the renderer's image in the window through the backend's own
// path: a Vulkan swapchain (hal_vulkan_present), or on OpenGL a blit into the window's default
// framebuffer followed by a buffer swap (the device runs on the window's context).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "hal/device.hpp"
#include "hal_registry/registry.hpp"

struct GLFWwindow;

namespace asvgf::demo {

// How the chosen backend presents (its registry entry says).
using WindowApi = hal::registry::Presentation;

// The window hints for `api` (before glfwCreateWindow) and, after it, the backend's device on the
// window (its context adopted, or the instance extensions a surface needs).
void set_window_hints(WindowApi api);
struct ValidationLog;
std::unique_ptr<hal::Device> open_window_device(const std::string& backend, GLFWwindow* window,
                                                const std::string& adapter, bool validation, ValidationLog& log);

class WindowPresenter {
 public:
  virtual ~WindowPresenter() = default;
  // Shows `image` (in State::Present) scaled to the window; nothing while the window has no area.
  virtual void present(hal::ImageHandle image) = 0;
  // What the presentation surface went through, for the run's last line ("swapchain created 2
  // times", "framebuffer at 2 sizes").
  virtual std::string history() const = 0;
};

std::unique_ptr<WindowPresenter> make_window_presenter(WindowApi api, hal::Device& device, GLFWwindow* window,
                                                       bool vsync);

}  // namespace asvgf::demo
