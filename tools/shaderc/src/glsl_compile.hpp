// glsl_compile.hpp: GLSL 460 compute source -> SPIR-V 1.5 for Vulkan 1.2, with glslang.
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

}  // namespace shaderc
