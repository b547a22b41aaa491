// glsl_compile.hpp: GLSL 460 compute source -> SPIR-V 1.5 for Vulkan 1.2, and the OpenGL
// translation -> SPIR-V 1.0 for OpenGL 4.5 (GL_ARB_gl_spirv), with glslang.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "options.hpp"

namespace shaderc {

struct GlslResult {
  std::vector<std::uint32_t> spirv;
  std::vector<std::filesystem::path> includes;  // every file #included, for the depfile
  std::vector<std::string> warnings;            // "file:line: warning: message"
};

// Throws ToolError holding glslang's errors as "file:line: error: message" lines; a message from
// an included file names that file.
GlslResult compile_glsl(const Options& options);

// The OpenGL backend's SPIR-V: `glsl`, the GLSL 450 translation (SPIRV-Cross's, with its GL binding
// units and combined samplers, so that the module follows GL's rules), compiled for OpenGL 4.5.
// Throws ToolError naming `shader` with glslang's log.
std::vector<std::uint32_t> compile_gl_spirv(const std::string& glsl, const std::string& shader);

}  // namespace shaderc
