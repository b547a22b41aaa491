// error.hpp: the one exception type of the tool. main() prints it and exits 1; every message is
// already formatted for a compiler-style log ("file:line: error: ..." or "<shader>: error: ...").
#pragma once

#include <stdexcept>
#include <string>

namespace shaderc {

struct ToolError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace shaderc
