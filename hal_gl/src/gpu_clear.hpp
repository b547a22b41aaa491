// Clears on the GPU. OpenGL ES 3.1 has neither glClearBufferSubData nor glClearTexImage, and
// uploading the value from the host cost about 0.6 s a GB on the H200, after which the buffer copied
// at a third of the bandwidth of one the GPU filled: so ES clears buffers by a compute dispatch and
// colour-renderable images through a framebuffer. Desktop OpenGL clears buffers by the same
// dispatch: a buffer glClearBufferSubData filled copied at 80-90% of the speed of one the dispatch
// filled on NVIDIA (docs/performance.md, "OpenGL's copy bandwidth").
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstdint>

namespace hal::gl {

class GpuClear {
 public:
  GpuClear() = default;
  GpuClear(const GpuClear&) = delete;
  GpuClear& operator=(const GpuClear&) = delete;
  ~GpuClear();  // with the context current

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
