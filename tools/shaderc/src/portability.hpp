// portability.hpp: the portability rules of DESIGN.md ("Shaders and the offline tool step"),
// checked on the reflection of the final SPIR-V. Each finding names the shader, the rule and the
// target (or the HAL) that would reject the shader, so the build log says what to change.
#pragma once

#include <string>
#include <vector>

#include "reflection.hpp"

namespace shaderc {

// One "<source>: error: <shader>: ..." line per broken rule; empty when the shader is portable.
// What of OpenGL ES 3.1's guaranteed compute limits (4 storage blocks, 4 image uniforms, 16
// textures, 12 uniform blocks) the shader exceeds, e.g. "6 storage blocks (ES 3.1 guarantees 4)";
// "fits" when none. WebGPU's limits (checked above) already keep every shader within OpenGL 4.5 on
// NVIDIA (8 image uniforms) and llvmpipe; an ES device with more than the minimum may still run it.
std::string es31_minimum_fit(const Reflection& reflection);

std::vector<std::string> check_portability(const Reflection& reflection, const std::string& shader,
                                           const std::string& source);

}  // namespace shaderc
