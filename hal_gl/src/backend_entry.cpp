// The OpenGL backend's two entries in the registry (hal_registry/registry.hpp): OpenGL 4.5 core
// and OpenGL ES 3.1, headless through EGL unless a window's context is adopted.
#include "hal_gl/gl.hpp"
#include "hal_registry/registry.hpp"

namespace hal::registry {

std::vector<Backend> hal_gl_backends() {
  auto entry = [](const char* name, const char* description, hal::gl::Flavour flavour, Presentation presentation) {
    Backend b;
    b.name = name;
    b.description = description;
    b.presentation = presentation;
    b.open = [flavour](const OpenOptions& o) {
      hal::gl::DeviceOptions options;
      options.flavour = flavour;
      options.on_message = o.on_message;
      options.make_current = o.make_current;
      return hal::gl::create_device(options);
    };
    b.environment_problem = [] { return hal::gl::environment_problem(); };
    return b;
  };
  return {entry("gl", "OpenGL 4.5 compute (software BVH)", hal::gl::Flavour::Gl, Presentation::OpenGlContext),
          entry("gles", "OpenGL ES 3.1 compute (software BVH)", hal::gl::Flavour::Gles, Presentation::OpenGlEsContext)};
}

}  // namespace hal::registry
