// Registers the OpenGL backend twice: OpenGL 4.5 core and OpenGL ES 3.1, both headless through
// EGL; GL debug-output errors fail the test.
#include "backends.hpp"
#include "hal_gl/gl.hpp"

namespace {

std::unique_ptr<hal::Device> create(hal::gl::Flavour flavour, std::vector<std::string>& messages) {
  hal::gl::DeviceOptions options;
  options.flavour = flavour;
  options.on_message = [&messages](const std::string& m) { messages.push_back(m); };
  return hal::gl::create_device(options);
}

const conformance::Register gl({"gl", [](std::vector<std::string>& m) { return create(hal::gl::Flavour::Gl, m); }});
const conformance::Register gles({"gles",
                                  [](std::vector<std::string>& m) { return create(hal::gl::Flavour::Gles, m); }});

}  // namespace
