// cross_compile.hpp: SPIR-V -> GLSL 450 (OpenGL), ESSL 310, HLSL and MSL with SPIRV-Cross.
// Each throws spirv_cross::CompilerError when SPIRV-Cross cannot express the module.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "reflection.hpp"

namespace shaderc {

// OpenGL GLSL 450 (es = false) or OpenGL ES GLSL 310 (es = true): descriptor sets are dropped, each
// resource takes its reflected per-kind GL unit (Binding::gl_binding), and each texture2D read
// with texelFetch becomes a sampler2D (GL has no separate images).
std::string to_glsl(const std::vector<std::uint32_t>& spirv, const Reflection& reflection, bool es);
// Shader model 6.5 when the module uses ray queries, else 6.0.
std::string to_hlsl(const std::vector<std::uint32_t>& spirv, bool ray_query);
// MSL 2.3 when the module uses ray queries, else 2.1.
std::string to_msl(const std::vector<std::uint32_t>& spirv, bool ray_query);

}  // namespace shaderc
