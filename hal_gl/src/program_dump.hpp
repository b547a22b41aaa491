// A porting probe: with ASVGF_GL_PROGRAM_DUMP=<folder>, every program the OpenGL backend links is
// written there as the driver's program binary (<shader>.bin: NVIDIA's holds its compiled assembly
// as text, with register and local-memory use) beside the GLSL it was compiled from
// (<shader>.glsl). Compare passes, and GL against the SPIR-V Vulkan runs (hal/PORTING.md).
// Its other half: with ASVGF_GL_PROGRAM_SOURCE=<folder>, a shader whose <shader>.glsl (<shader>.essl
// on OpenGL ES) lies there is compiled from that file instead of its embedded source, so that a
// porter can time an edited program (a dumped one, changed by hand) without rebuilding.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <string_view>

namespace hal::gl {

// Whether the dump is on: then call before glLinkProgram, so the driver keeps the binary.
bool program_dump_enabled();
// Writes the linked program's binary and its source; a failure is printed, never thrown.
void dump_program(GLuint program, std::string_view shader_name, std::string_view source);
// The replacement source for a shader from ASVGF_GL_PROGRAM_SOURCE's folder, or "" where there is
// none; a replacement is announced on stderr, a file that cannot be read throws.
std::string program_source_override(std::string_view shader_name, bool es);

}  // namespace hal::gl
