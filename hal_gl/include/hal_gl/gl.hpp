// hal_gl/gl.hpp: the OpenGL implementation of the HAL: compute shaders on OpenGL 4.5 core or
// OpenGL ES 3.1, in a headless EGL context (Mesa's surfaceless platform, else the EGL device
// platform, as NVIDIA's driver offers). Nothing outside hal_gl includes a GL or EGL header.
//
// It has no acceleration structures (capabilities say so: the frame picks its software-BVH
// variants) and runs the GLSL 450 / ESSL 310 the shader tool embeds in each ShaderInfo, binding
// each resource at its ShaderBinding::gl_binding unit. Command lists are recorded on the host and
// replayed into the context at submit. Use the device behind hal::validate::wrap like any other.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "hal/device.hpp"

namespace hal::gl {

enum class Flavour { Gl, Gles };  // OpenGL 4.5 core, OpenGL ES 3.1

struct DeviceOptions {
  Flavour flavour = Flavour::Gl;
  // GL debug-output errors (KHR_debug) go here; stderr when empty.
  std::function<void(const std::string&)> on_message;
  // Set: adopt the context current on the calling thread (a window's, e.g. GLFW's) instead of
  // creating a headless one; the device calls this to make that context current again before its
  // GL calls. The context must be OpenGL 4.5+ core for Flavour::Gl, OpenGL ES 3.1+ for Gles.
  std::function<void()> make_current;
};

// Creates a device on a new context of `options.flavour`. Throws hal::Error(NoDevice) when EGL or
// the context cannot be created (naming the EGL error), Unsupported when the context lacks compute.
std::unique_ptr<hal::Device> create_device(const DeviceOptions& options = {});

// What is wrong with ASVGF_GL_SHADERS (unset, glsl or spirv), naming it and the valid values; ""
// when nothing is. create_device throws hal::Error(InvalidUsage) with the same.
std::string environment_problem();

// Shows `image` (in State::Present, created with CopySrc usage, a float or unorm format) on the
// default framebuffer of the device's adopted context, scaled to width x height with a linear
// blit, its first row at the top. The caller swaps the buffers. Throws InvalidUsage when `device`
// (or the device behind the validation layer) is not an OpenGL device with an adopted context.
void present(hal::Device& device, hal::ImageHandle image, std::uint32_t width, std::uint32_t height);

}  // namespace hal::gl
