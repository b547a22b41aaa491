// wgsl.hpp: SPIR-V -> WGSL with naga, by running naga_to_wgsl.mjs in Node (SPIRV-Cross has no
// WGSL backend).
#pragma once

#include <filesystem>
#include <string>

#include "options.hpp"

namespace shaderc {

// Translates the .spv already written at `spv`; returns the WGSL text. Throws ToolError naming
// the shader and WGSL with naga's report.
std::string to_wgsl(const Options& options, const std::filesystem::path& spv);

}  // namespace shaderc
