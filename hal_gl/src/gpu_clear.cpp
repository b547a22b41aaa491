#include "gpu_clear.hpp"

#include <algorithm>
#include <string>

#include "hal/error.hpp"

namespace hal::gl {
namespace {

constexpr std::uint32_t kGroupSize = 256;
constexpr std::uint64_t kMaxGroups = 65535;  // per dimension: ES 3.1's guaranteed minimum

const char* const kClearSource = R"(#version 310 es
layout(local_size_x = 256) in;
layout(std430, binding = 0) writeonly buffer Words { uint words[]; };
uniform uint word_count;
uniform uint word;
uniform uint row_words;  // words a row of workgroups covers (a dispatch has up to 65535 a row)
void main() {
  uint i = gl_WorkGroupID.y * row_words + gl_GlobalInvocationID.x;
  if (i < word_count) words[i] = word;
}
)";

GLuint compile_clear_program() {
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &kClearSource, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  const GLuint program = glCreateProgram();
  if (ok) {
    glAttachShader(program, shader);
    glLinkProgram(program);
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
  }
  glDeleteShader(shader);
  if (!ok) {
    glDeleteProgram(program);
    throw Error(ErrorKind::Backend, "clear_buffer", "the OpenGL ES driver rejects the buffer clear's compute program");
  }
  return program;
}

bool integer_format(GLenum internal_format) {
  return internal_format == GL_R32UI || internal_format == GL_RG32UI || internal_format == GL_RGBA32UI ||
         internal_format == GL_RGBA16UI;
}

}  // namespace

GpuClear::~GpuClear() {
  if (program_) glDeleteProgram(program_);
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
}

void GpuClear::buffer(GLuint buffer, std::uint64_t words, std::uint32_t word) {
  if (words == 0) return;
  if (!program_) {
    program_ = compile_clear_program();
    count_location_ = glGetUniformLocation(program_, "word_count");
    word_location_ = glGetUniformLocation(program_, "word");
    row_location_ = glGetUniformLocation(program_, "row_words");
  }
  const std::uint64_t groups = (words + kGroupSize - 1) / kGroupSize;
  const std::uint64_t x = std::min(groups, kMaxGroups);
  const std::uint64_t y = (groups + x - 1) / x;
  glUseProgram(program_);  // every dispatch binds its own program and bindings again
  glUniform1ui(count_location_, static_cast<GLuint>(words));
  glUniform1ui(word_location_, word);
  glUniform1ui(row_location_, static_cast<GLuint>(x * kGroupSize));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  glDispatchCompute(static_cast<GLuint>(x), static_cast<GLuint>(y), 1);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glUseProgram(0);
  // The HAL orders a clear like a copy, which GL keeps on its own; a shader's writes it does not.
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

bool GpuClear::image(GLuint texture, GLenum internal_format, std::array<float, 4> value) {
  if (!framebuffer_) glGenFramebuffers(1, &framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  const bool renderable = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  if (renderable) {
    if (integer_format(internal_format)) {
      // As the host conversion (formats.cpp's texels_of): negative to 0, then truncated.
      GLuint words[4];
      for (int c = 0; c < 4; ++c) words[c] = value[c] <= 0.0f ? 0u : static_cast<GLuint>(value[c]);
      glClearBufferuiv(GL_COLOR, 0, words);
    } else {
      glClearBufferfv(GL_COLOR, 0, value.data());
    }
  }
  glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  return renderable;
}

}  // namespace hal::gl
