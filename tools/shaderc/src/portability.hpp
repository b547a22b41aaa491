// portability.hpp: the portability rules of DESIGN.md ("Shaders and the offline tool step"),
// checked on the reflection of the final SPIR-V. Each finding names the shader, the rule and the
// target (or the HAL) that would reject the shader, so the build log says what to change.
#pragma once

#include <string>
#include <vector>

#include "reflection.hpp"

namespace shaderc {

// One "<source>: error: <shader>: ..." line per broken rule; empty when the shader is portable.
std::vector<std::string> check_portability(const Reflection& reflection, const std::string& shader,
                                           const std::string& source);

}  // namespace shaderc
