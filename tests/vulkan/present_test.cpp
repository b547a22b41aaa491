// Presentation through GLFW (run under xvfb-run by CTest): frames show, resizes recreate the
// swapchain, validation stays silent.
#include <vulkan/vulkan.h>
#include <GLFW/glfw3.h>

#include <chrono>
#include <thread>

#include "hal_vulkan/presenter.hpp"
#include "validated_device.hpp"

TEST_CASE("vulkan presenter: HAL images reach the window and resizes recreate the swapchain") {
  if (!glfwInit()) {
    MESSAGE("no display (glfwInit failed): presentation not tested; run under xvfb-run");
    return;
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  GLFWwindow* window = glfwCreateWindow(96, 64, "asvgf presenter test", nullptr, nullptr);
  REQUIRE(window != nullptr);
  {
    hal::vulkan::DeviceOptions options;
    options.instance_extensions = hal::vulkan::glfw_instance_extensions();
    ValidatedDevice device(options);

    constexpr std::uint32_t w = 64, h = 48;
    const auto image = device->create_image(
        {"presented", w, h, hal::Format::RGBA8Unorm, hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst});
    std::vector<std::uint8_t> pixels(w * h * 4);
    for (std::uint32_t i = 0; i < w * h; ++i) {
      pixels[4 * i] = static_cast<std::uint8_t>(i % w * 4);
      pixels[4 * i + 1] = static_cast<std::uint8_t>(i / w * 5);
      pixels[4 * i + 2] = 128;
      pixels[4 * i + 3] = 255;
    }
    device->upload_image(image, std::as_bytes(std::span(pixels)));
    auto cmd = device->create_command_list("to present");
    cmd->barrier({image, hal::State::CopyDst, hal::State::Present});
    device->submit(*cmd);
    device->wait();

    {
      hal::vulkan::Presenter presenter(*device, window);
      for (int frame = 0; frame < 4; ++frame) {
        glfwPollEvents();
        CHECK(presenter.present(image));
      }
      int fw = 0, fh = 0;
      glfwGetFramebufferSize(window, &fw, &fh);
      CHECK(presenter.extent() == std::pair<std::uint32_t, std::uint32_t>(fw, fh));
      const auto generation = presenter.swapchain_generation();

      glfwSetWindowSize(window, 160, 100);
      for (int tries = 0; tries < 50; ++tries) {  // the X server applies the size asynchronously
        glfwPollEvents();
        glfwGetFramebufferSize(window, &fw, &fh);
        if (fw == 160) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      for (int frame = 0; frame < 4; ++frame) {
        glfwPollEvents();
        CHECK(presenter.present(image));
      }
      glfwGetFramebufferSize(window, &fw, &fh);
      CHECK(fw == 160);
      CHECK(presenter.extent() == std::pair<std::uint32_t, std::uint32_t>(fw, fh));
      CHECK(presenter.swapchain_generation() > generation);
      device->wait();
    }
  }
  glfwDestroyWindow(window);
  glfwTerminate();
}
