// EGL without a window system: Mesa's surfaceless platform, else the first EGL device (NVIDIA).
#include "context.hpp"

#include <cstdio>
#include <utility>
#include <vector>

#include "hal/error.hpp"

namespace hal::gl {
namespace {

std::string egl_error() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return buf;
}

bool has_client_extension(const char* name) {
  const char* all = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  return all && epoxy_extension_in_string(all, name);
}

EGLDisplay open_display(std::string& platform) {
  if (has_client_extension("EGL_MESA_platform_surfaceless")) {
    EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
      platform = "surfaceless";
      return d;
    }
  }
  if (has_client_extension("EGL_EXT_platform_device") && has_client_extension("EGL_EXT_device_enumeration")) {
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (count > 0 && eglQueryDevicesEXT(count, devices.data(), &count)) {
      for (EGLDeviceEXT device : devices) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
          platform = "device";
          return d;
        }
      }
    }
  }
  throw Error(ErrorKind::NoDevice, "OpenGL",
              "no headless EGL display (neither EGL_MESA_platform_surfaceless nor an EGL device): " + egl_error());
}

}  // namespace

Context::Context(Flavour flavour) : flavour_(flavour) {
  display_ = open_display(platform_);
  const bool es = flavour == Flavour::Gles;
  if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
    eglTerminate(display_);
    throw Error(ErrorKind::NoDevice, es ? "OpenGL ES" : "OpenGL", "EGL cannot bind the API: " + egl_error());
  }
  std::vector<EGLint> attributes = {EGL_CONTEXT_MAJOR_VERSION, es ? 3 : 4, EGL_CONTEXT_MINOR_VERSION, es ? 1 : 5};
  if (!es) attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT});
  attributes.push_back(EGL_NONE);
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes.data());
  if (context_ == EGL_NO_CONTEXT) {
    const std::string why = egl_error();
    eglTerminate(display_);
    throw Error(ErrorKind::NoDevice, es ? "OpenGL ES 3.1" : "OpenGL 4.5",
                "EGL cannot create the context (" + platform_ + " platform): " + why);
  }
  make_current();
}

Context::Context(Flavour flavour, std::function<void()> adopt)
    : flavour_(flavour), platform_("adopted"), adopt_(std::move(adopt)) {
  make_current();
}

Context::~Context() {
  if (adopted()) return;  // the caller's context outlives the device
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  // The display is left initialised: terminating it would end other devices' contexts on it.
}

void Context::make_current() const {
  if (adopted()) return adopt_();
  if (eglGetCurrentContext() == context_) return;
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
    throw Error(ErrorKind::DeviceLost, "OpenGL", "cannot make the context current: " + egl_error());
}

}  // namespace hal::gl
