// A headless EGL context of one flavour; made current before every call into GL.
#pragma once

#include <epoxy/egl.h>

#include <string>

#include "hal_gl/gl.hpp"

namespace hal::gl {

class Context {
 public:
  explicit Context(Flavour flavour);  // throws hal::Error(NoDevice)
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  void make_current() const;
  Flavour flavour() const { return flavour_; }
  const std::string& platform() const { return platform_; }  // "surfaceless" or "device"

 private:
  Flavour flavour_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string platform_;
};

}  // namespace hal::gl
