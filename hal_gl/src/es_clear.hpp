// OpenGL ES 3.1 has neither glClearBufferSubData nor glClearTexImage. Uploading the value from the
// host instead cost about 0.6 s a GB on the H200, and a buffer the host filled copied at a third of
// the bandwidth of one the GPU filled (docs/performance.md): so ES clears on the GPU too, buffers
// by a compute dispatch and colour-renderable images through a framebuffer.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstdint>

namespace hal::gl {

class EsClear {
 public:
  EsClear() = default;
  EsClear(const EsClear&) = delete;
  EsClear& operator=(const EsClear&) = delete;
  ~EsClear();  // with the context current

  // Every 32-bit word of `buffer`'s first `words` to `word`; makes the writes visible to every later use.
  void buffer(GLuint buffer, std::uint64_t words, std::uint32_t word);
  // `texture` (GL_TEXTURE_2D, `internal_format`) to `value` where the format is colour-renderable
  // here; false where it is not (the caller uploads).
  bool image(GLuint texture, GLenum internal_format, std::array<float, 4> value);

 private:
  GLuint program_ = 0;
  GLint count_location_ = -1, word_location_ = -1, row_location_ = -1;
  GLuint framebuffer_ = 0;
};

}  // namespace hal::gl
