// The device's context: a headless EGL context of one flavour, or one the caller made (a window's)
// and lends with a callback that makes it current. Made current before every call into GL.
#pragma once

#include <epoxy/egl.h>

#include <functional>
#include <string>

#include "hal_gl/gl.hpp"

namespace hal::gl {

class Context {
 public:
  explicit Context(Flavour flavour);  // headless; throws hal::Error(NoDevice)
  Context(Flavour flavour, std::function<void()> adopt);  // the caller's context, current now
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  void make_current() const;
  Flavour flavour() const { return flavour_; }
  const std::string& platform() const { return platform_; }  // "surfaceless", "device" or "adopted"
  bool adopted() const { return static_cast<bool>(adopt_); }

 private:
  Flavour flavour_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string platform_;
  std::function<void()> adopt_;
};

}  // namespace hal::gl
