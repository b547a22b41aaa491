// spirv_tools.hpp: SPIRV-Tools optimisation and validation, for the Vulkan 1.2 environment (the
// same rules `spirv-val --target-env vulkan1.2` applies) or OpenGL 4.5 (GL_ARB_gl_spirv).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace shaderc {

enum class SpirvEnv { Vulkan12, OpenGl45 };

// Performance passes; keeps names (OpName) because reflection binds resources by name.
// Throws ToolError naming `shader` if the optimiser rejects the module.
std::vector<std::uint32_t> optimize_spirv(const std::vector<std::uint32_t>& spirv, const std::string& shader,
                                          SpirvEnv env = SpirvEnv::Vulkan12);

// Throws ToolError naming `shader` with the validator's messages.
void validate_spirv(const std::vector<std::uint32_t>& spirv, const std::string& shader,
                    SpirvEnv env = SpirvEnv::Vulkan12);

}  // namespace shaderc
