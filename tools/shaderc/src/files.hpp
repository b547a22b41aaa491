// files.hpp: small file helpers. Outputs are written only when their content changes, so Ninja
// (custom commands restat their outputs) does not rebuild C++ that includes an unchanged header.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace shaderc {

std::string read_file(const std::filesystem::path& path);                            // throws ToolError
void write_if_changed(const std::filesystem::path& path, std::string_view content);  // throws ToolError
void remove_stale(const std::filesystem::path& path);  // a target no longer emitted for this variant

}  // namespace shaderc
