#include "files.hpp"

#include <fstream>
#include <iterator>
#include <system_error>

#include "error.hpp"

namespace shaderc {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ToolError(path.string() + ": error: cannot open file");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_if_changed(const std::filesystem::path& path, std::string_view content) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    std::ifstream in(path, std::ios::binary);
    std::string old{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (old == content) return;
  }
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  // Write next to the target and rename, so an interrupted build never leaves half a file.
  auto tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out) throw ToolError(path.string() + ": error: cannot write file");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw ToolError(path.string() + ": error: cannot write file: " + ec.message());
}

void remove_stale(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
}

}  // namespace shaderc
