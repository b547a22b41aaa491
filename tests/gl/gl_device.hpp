// Test helper: a headless OpenGL device of one flavour behind the HAL validation layer, whose
// debug-output errors go to `messages` (the test fails on them), and the flavour's short name.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "hal/validate.hpp"
#include "hal_gl/gl.hpp"

inline std::unique_ptr<hal::Device> open_gl(hal::gl::Flavour flavour, std::vector<std::string>& messages) {
  hal::gl::DeviceOptions options;
  options.flavour = flavour;
  options.on_message = [&messages](const std::string& m) { messages.push_back(m); };
  return hal::validate::wrap(hal::gl::create_device(options));
}

inline std::string flavour_name(hal::gl::Flavour flavour) {
  return flavour == hal::gl::Flavour::Gl ? "gl" : "gles";
}
