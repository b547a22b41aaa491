#include "program_dump.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hal/error.hpp"

namespace hal::gl {
namespace {

const char* dump_folder() {
  const char* folder = std::getenv("ASVGF_GL_PROGRAM_DUMP");
  return folder && *folder ? folder : nullptr;
}

bool write(const std::filesystem::path& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  return static_cast<bool>(out);
}

}  // namespace

bool program_dump_enabled() {
  return dump_folder() != nullptr;
}

void dump_program(GLuint program, std::string_view shader_name, std::string_view source) {
  const char* folder = dump_folder();
  if (!folder) return;
  GLint length = 0;
  glGetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &length);
  std::vector<char> binary(static_cast<std::size_t>(std::max(length, 0)));
  GLenum format = 0;
  GLsizei written = 0;
  if (length > 0) glGetProgramBinary(program, length, &written, &format, binary.data());
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  const std::filesystem::path base = std::filesystem::path(folder) / std::string(shader_name);
  const bool ok = written > 0 && write(base.string() + ".bin", binary.data(), static_cast<std::size_t>(written)) &&
                  write(base.string() + ".glsl", source.data(), source.size());
  if (!ok)
    std::fprintf(stderr, "ASVGF_GL_PROGRAM_DUMP: could not write %s.bin/.glsl (binary of %d bytes)\n",
                 base.string().c_str(), static_cast<int>(written));
}

std::string program_source_override(std::string_view shader_name, bool es) {
  const char* folder = std::getenv("ASVGF_GL_PROGRAM_SOURCE");
  if (!folder || !*folder) return "";
  const std::filesystem::path path =
      std::filesystem::path(folder) / (std::string(shader_name) + (es ? ".essl" : ".glsl"));
  std::error_code ec;
  // A folder that is not there (a typo) would otherwise time the embedded programs unannounced.
  if (!std::filesystem::is_directory(folder, ec))
    throw Error(ErrorKind::InvalidUsage, folder, "ASVGF_GL_PROGRAM_SOURCE: no such folder");
  if (!std::filesystem::is_regular_file(path, ec)) return "";
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || text.str().empty())
    throw Error(ErrorKind::InvalidUsage, path.string(),
                "ASVGF_GL_PROGRAM_SOURCE: cannot read this file, or it is empty");
  std::fprintf(stderr, "ASVGF_GL_PROGRAM_SOURCE: '%s' compiled from %s\n", std::string(shader_name).c_str(),
               path.string().c_str());
  return text.str();
}

}  // namespace hal::gl
