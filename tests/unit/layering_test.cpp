// The denoiser library has one door: its public headers (include/asvgf, with the HAL's). Reads every
// C++ file and checks its quoted includes against the layering:
//   - the renderer, the report, io and the apps include nothing of the library's implementation
//     (pipeline/denoiser/...): they use asvgf/ and hal*/ headers as any other renderer would;
//   - the library (pipeline/denoiser and include/asvgf) includes nothing of the renderer, the
//     report, io or the CPU oracle;
//   - a public header includes only public headers (asvgf/, hal/): what `cmake --install` installs
//     must compile on its own.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The quoted includes of `text`, with their line numbers.
std::vector<std::pair<int, std::string>> quoted_includes(const std::string& text) {
  static const std::regex include(R"(^\s*#\s*include\s*"([^"]+)\")");
  std::vector<std::pair<int, std::string>> found;
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    std::smatch m;
    if (std::regex_search(line, m, include)) found.emplace_back(number, m[1].str());
  }
  return found;
}

bool starts_with_any(const std::string& path, std::initializer_list<const char*> prefixes) {
  for (const char* p : prefixes)
    if (path.rfind(p, 0) == 0) return true;
  return false;
}

// Why `file` (relative to the repository) may not include `header`, or "" when it may.
std::string layering_violation(const std::string& file, const std::string& header) {
  const bool public_header = file.rfind("include/asvgf/", 0) == 0;
  const bool library = public_header || file.rfind("pipeline/denoiser/", 0) == 0;
  const bool library_user = starts_with_any(file, {"pipeline/renderer/", "pipeline/report/", "pipeline/io/", "apps/"});
  if (library_user && header.rfind("denoiser/", 0) == 0)
    return "the renderer and the apps reach the denoiser through asvgf/ headers only";
  if (library && starts_with_any(header, {"renderer/", "report/", "io/", "cpu_oracle/"}))
    return "the denoiser library includes nothing of the renderer or its tools";
  if (public_header && !starts_with_any(header, {"asvgf/", "hal/"}))
    return "a public header includes only public headers (asvgf/, hal/)";
  return "";
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE(
    "layering: the renderer reaches the denoiser only through its public headers, and the library includes nothing "
    "above it") {
  const fs::path root = ASVGF_SOURCE_DIR;
  int files = 0, includes = 0;
  for (const char* folder : {"apps", "pipeline", "include"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
      const auto ext = entry.path().extension();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
      const std::string file = entry.path().lexically_relative(root).generic_string();
      ++files;
      for (const auto& [line, header] : quoted_includes(read(entry.path()))) {
        ++includes;
        const std::string why = layering_violation(file, header);
        if (!why.empty()) FAIL_CHECK(file << ":" << line << " includes \"" << header << "\": " << why);
      }
    }
  }
  CHECK(files > 100);
  CHECK(includes > 200);  // 288 when written: the scan reads what it should
}

TEST_CASE("layering: the check finds each kind of crossing as it was written before the one door") {
  CHECK(quoted_includes("#include <vector>\n  #include \"denoiser/graph/graph_runtime.hpp\"\n").size() == 1);
  CHECK(!layering_violation("pipeline/renderer/frame_graph.hpp", "denoiser/passes/temporal.hpp").empty());
  CHECK(!layering_violation("apps/demo/title.hpp", "denoiser/graph/graph_runtime.hpp").empty());
  CHECK(!layering_violation("pipeline/denoiser/passes/atrous.cpp", "renderer/scene_gpu.hpp").empty());
  CHECK(!layering_violation("include/asvgf/denoiser.hpp", "denoiser/passes/temporal.hpp").empty());
  CHECK(layering_violation("pipeline/renderer/frame_graph.hpp", "asvgf/denoiser_graph.hpp").empty());
  CHECK(layering_violation("pipeline/denoiser/passes/atrous.cpp", "denoiser/passes/atrous.hpp").empty());
  CHECK(layering_violation("include/asvgf/denoiser.hpp", "hal/device.hpp").empty());
}
