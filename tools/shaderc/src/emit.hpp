// emit.hpp: the generated C++ header and the reflection JSON of one shader variant.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "options.hpp"
#include "reflection.hpp"

namespace shaderc {

// Target extension -> file written ("hal_test_scale.hlsl") or why it was not ("skipped": reason).
struct Targets {
  std::map<std::string, std::string> emitted;
  std::map<std::string, std::string> skipped;
};

// `namespace asvgf::shaders { inline constexpr hal::ShaderInfo <cpp_name> = {...}; }`
// `glsl` and `essl` (the OpenGL outputs, empty when not emitted) are embedded as source text, and
// `gl_spirv` (OpenGL's SPIR-V, empty when not emitted) as the bytes of source "spirv-gl".
std::string header_text(const Options& options, const Reflection& reflection, const std::vector<std::uint32_t>& spirv,
                        const std::string& glsl, const std::string& essl, const std::vector<std::uint32_t>& gl_spirv);

// Stable (sorted keys, no paths, no SPIR-V) so that golden files can compare it byte for byte.
std::string json_text(const Options& options, const Reflection& reflection, const Targets& targets);

}  // namespace shaderc
