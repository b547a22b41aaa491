// Presentation on the OpenGL backend (run under xvfb-run by CTest): the device adopts a GLFW
// window's context, hal::gl::present blits an image into the window's back buffer with its first
// row on top, and a headless device refuses to present.
#include <doctest/doctest.h>
// epoxy before GLFW: GLFW would include the system GL header, which epoxy replaces.
#include <epoxy/gl.h>
// clang-format off
#include <GLFW/glfw3.h>
// clang-format on

#include <string>
#include <vector>

#include "hal/error.hpp"
#include "hal/validate.hpp"
#include "hal_gl/gl.hpp"

namespace {

// An image whose every pixel says where it is: red = column, green = row.
std::vector<std::uint8_t> coordinates(std::uint32_t w, std::uint32_t h) {
  std::vector<std::uint8_t> pixels(std::size_t(w) * h * 4);
  for (std::uint32_t i = 0; i < w * h; ++i) {
    pixels[4 * i] = static_cast<std::uint8_t>(i % w * 3);
    pixels[4 * i + 1] = static_cast<std::uint8_t>(i / w * 5);
    pixels[4 * i + 2] = 77;
    pixels[4 * i + 3] = 255;
  }
  return pixels;
}

}  // namespace

TEST_CASE("gl presenter: an image reaches the window's back buffer pixel for pixel, first row on top") {
  if (!glfwInit()) {
    MESSAGE("no display (glfwInit failed): presentation not tested; run under xvfb-run");
    return;
  }
  constexpr std::uint32_t w = 64, h = 48;
  for (const auto flavour : {hal::gl::Flavour::Gl, hal::gl::Flavour::Gles}) {
    const bool es = flavour == hal::gl::Flavour::Gles;
    CAPTURE(es);
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, es ? GLFW_OPENGL_ES_API : GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, es ? 3 : 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, es ? 1 : 5);
    if (!es) glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(int(w), int(h), "asvgf gl presenter test", nullptr, nullptr);
    REQUIRE(window != nullptr);
    {
      std::vector<std::string> messages;
      hal::gl::DeviceOptions options;
      options.flavour = flavour;
      options.on_message = [&messages](const std::string& m) { messages.push_back(m); };
      options.make_current = [window] {
        if (glfwGetCurrentContext() != window) glfwMakeContextCurrent(window);
      };
      glfwMakeContextCurrent(window);
      const auto device = hal::validate::wrap(hal::gl::create_device(options));
      const auto image =
          device->create_image({"presented", w, h, hal::Format::RGBA8Unorm,
                                hal::ImageUsage::Sampled | hal::ImageUsage::CopySrc | hal::ImageUsage::CopyDst});
      const auto pixels = coordinates(w, h);
      device->upload_image(image, std::as_bytes(std::span(pixels)));
      auto commands = device->create_command_list("to present");
      commands->barrier({image, hal::State::CopyDst, hal::State::Present});
      device->submit(*commands);
      device->wait();

      int fw = 0, fh = 0;
      glfwGetFramebufferSize(window, &fw, &fh);
      REQUIRE(fw == int(w));
      REQUIRE(fh == int(h));
      hal::gl::present(*device, image, w, h);
      // Read the back buffer before the swap: GL rows run bottom-up, so window row y is image row h-1-y.
      std::vector<std::uint8_t> shown(pixels.size());
      glReadBuffer(GL_BACK);
      glReadPixels(0, 0, GLsizei(w), GLsizei(h), GL_RGBA, GL_UNSIGNED_BYTE, shown.data());
      int wrong = 0;
      for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x)
          for (int c = 0; c < 3; ++c) wrong += shown[4 * ((h - 1 - y) * w + x) + c] != pixels[4 * (y * w + x) + c];
      MESSAGE(std::string(es ? "gles" : "gl") << ": " << wrong << " channels differ from the image");
      CHECK(wrong == 0);
      glfwSwapBuffers(window);
      for (const auto& m : messages) FAIL_CHECK("OpenGL: " << m);
    }
    glfwDestroyWindow(window);
  }
  glfwTerminate();

  const auto headless = hal::validate::wrap(hal::gl::create_device());
  const auto image = headless->create_image({"never shown", 4, 4, hal::Format::RGBA8Unorm, hal::ImageUsage::CopySrc});
  CHECK_THROWS_WITH_AS(hal::gl::present(*headless, image, 4, 4), doctest::Contains("headless"), hal::Error);
}
