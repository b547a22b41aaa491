// hal::Format as OpenGL internal format, pixel format and type.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <vector>

#include "hal/types.hpp"

namespace hal::gl {

struct GlFormat {
  GLenum internal = 0;  // GL_RGBA16F, ...
  GLenum format = 0;    // GL_RGBA, GL_RED_INTEGER, ...
  GLenum type = 0;      // GL_HALF_FLOAT, ...
};
GlFormat gl_format(Format format);

// OpenGL ES 3.1 image load/store takes only 1- and 4-channel 32-bit, rgba16f and rgba8 formats.
bool es_storage_format(Format format);

// One texel of `format` holding `value` (as clear_image converts it), repeated `count` times.
std::vector<std::byte> texels_of(Format format, std::array<float, 4> value, std::size_t count);

}  // namespace hal::gl
