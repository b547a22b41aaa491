#include "window_presenter.hpp"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <utility>

#include "app.hpp"
#include "hal_gl/gl.hpp"
#include "hal_vulkan/presenter.hpp"
#include "hal_vulkan/vulkan.hpp"  // glfw_instance_extensions
#include "scene_options.hpp"

namespace asvgf::demo {
namespace {

class VulkanWindowPresenter final : public WindowPresenter {
 public:
  VulkanWindowPresenter(hal::Device& device, GLFWwindow* window, bool vsync) : presenter_(device, window, vsync) {}
  void present(hal::ImageHandle image) override { presenter_.present(image); }
  std::string history() const override {
    return "swapchain created " + std::to_string(presenter_.swapchain_generation()) + " times";
  }

 private:
  hal::vulkan::Presenter presenter_;
};

class GlWindowPresenter final : public WindowPresenter {
 public:
  GlWindowPresenter(hal::Device& device, GLFWwindow* window, bool vsync) : device_(device), window_(window) {
    glfwSwapInterval(vsync ? 1 : 0);
  }
  void present(hal::ImageHandle image) override {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    if (w <= 0 || h <= 0) return;
    if (std::pair(w, h) != size_) {
      size_ = {w, h};
      ++sizes_;
    }
    hal::gl::present(device_, image, static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h));
    glfwSwapBuffers(window_);
  }
  std::string history() const override { return "framebuffer at " + std::to_string(sizes_) + " sizes"; }

 private:
  hal::Device& device_;
  GLFWwindow* window_;
  std::pair<int, int> size_{0, 0};
  int sizes_ = 0;
};

}  // namespace

void set_window_hints(WindowApi api) {
  if (api == WindowApi::VulkanSurface) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    return;
  }
  const bool es = api == WindowApi::OpenGlEsContext;
  glfwWindowHint(GLFW_CLIENT_API, es ? GLFW_OPENGL_ES_API : GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, es ? 3 : 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, es ? 1 : 5);
  if (!es) glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
}

std::unique_ptr<hal::Device> open_window_device(const std::string& backend, GLFWwindow* window,
                                                const std::string& adapter, bool validation, ValidationLog& log) {
  const auto& entry = hal::registry::backend(backend);
  hal::registry::OpenOptions options;
  options.adapter = adapter;
  options.validation = validation;
  // Validation messages and OpenGL's debug-output errors (always on) count alike.
  options.on_message = [&log](const std::string& message) {
    ++log.messages;
    std::fprintf(stderr, "%s\n", message.c_str());
  };
  if (entry.presentation == WindowApi::VulkanSurface) {
    options.instance_extensions = hal::vulkan::glfw_instance_extensions();
  } else {
    options.make_current = [window] {
      if (glfwGetCurrentContext() != window) glfwMakeContextCurrent(window);
    };
    glfwMakeContextCurrent(window);
  }
  return cli::app_device(entry.open(options));
}

std::unique_ptr<WindowPresenter> make_window_presenter(WindowApi api, hal::Device& device, GLFWwindow* window,
                                                       bool vsync) {
  if (api == WindowApi::VulkanSurface) return std::make_unique<VulkanWindowPresenter>(device, window, vsync);
  return std::make_unique<GlWindowPresenter>(device, window, vsync);
}

}  // namespace asvgf::demo
