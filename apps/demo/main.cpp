// asvgf-demo: a window in which the sphere light and the camera move under the mouse and keys and
// the denoiser reacts live. Exit codes: 0 success, 1 runtime failure (no display, no device),
// 2 bad command line, 3 the validation layer reported something (--validation).
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <exception>

#include "app.hpp"
#include "hal/error.hpp"
#include "options.hpp"

namespace {

struct Glfw {
  Glfw() {
    glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
    ok = glfwInit() == GLFW_TRUE;
  }
  ~Glfw() {
    if (window) glfwDestroyWindow(window);
    if (ok) glfwTerminate();
  }
  Glfw(const Glfw&) = delete;
  Glfw& operator=(const Glfw&) = delete;
  bool ok = false;
  GLFWwindow* window = nullptr;
};

// The window starts at --window, else at the render size scaled by a whole factor to >= 512.
asvgf::demo::Size window_size(const asvgf::demo::DemoOptions& o) {
  if (o.window_size) return *o.window_size;
  const std::uint32_t side = std::max(o.scene.width, o.scene.height);
  const std::uint32_t scale = std::max(1u, (512 + side - 1) / side);
  return {o.scene.width * scale, o.scene.height * scale};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"asvgf-demo: move the light and the camera and watch A-SVGF (or raw, EMA, SVGF, an accumulating "
               "reference) denoise the path-traced frames live",
               "asvgf-demo"};
  cli.set_version_flag("--version", std::string("asvgf-demo ") + ASVGF_VERSION);
  asvgf::demo::DemoOptions options;
  asvgf::demo::add_demo_options(cli, options);
  try {
    cli.parse(argc, argv);
    asvgf::demo::finish(options);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "asvgf-demo: error: %s\nRun 'asvgf-demo --help' for the options and controls.\n", e.what());
    return 2;
  }

  asvgf::demo::ValidationLog log;
  int code = 0;
  try {
    Glfw glfw;
    if (!glfw.ok) {
      std::fprintf(stderr, "asvgf-demo: no display (glfwInit failed); run it on a desktop or under xvfb-run\n");
      return 1;
    }
    const auto size = window_size(options);
    const auto api = hal::registry::backend(options.scene.backend).presentation;
    asvgf::demo::set_window_hints(api);
    glfw.window = glfwCreateWindow(static_cast<int>(size.width), static_cast<int>(size.height), "asvgf-demo", nullptr,
                                   nullptr);
    if (!glfw.window) {
      std::fprintf(stderr, "asvgf-demo: could not create a window%s\n",
                   api == asvgf::demo::WindowApi::OpenGlContext     ? " with an OpenGL 4.5 core context"
                   : api == asvgf::demo::WindowApi::OpenGlEsContext ? " with an OpenGL ES 3.1 context"
                                                                    : "");
      return 1;
    }
    asvgf::demo::App app(options, api, glfw.window, log);
    code = app.run();
  } catch (const hal::Error& e) {
    std::fprintf(stderr, "asvgf-demo: %s\n", e.what());
    code = 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "asvgf-demo: error: %s\n", e.what());
    code = 1;
  }
  // Counted after the device is gone: messages at destruction count too.
  if (options.scene.validation) {
    std::printf("validation messages: %d\n", log.messages.load());
    if (log.messages > 0 && code == 0) code = 3;
  }
  return code;
}
