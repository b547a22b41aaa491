// A backend is chosen through the registry (hal_registry/registry.hpp) and nowhere else: no source
// file compares a string with a backend's name. Reads every C++ file of the repository (but the
// backends' own registry entries, which give the names) for a name in quotes next to == or !=, or
// in a list of accepted values (CLI11's IsMember), as `backend == "gl"` was before the registry.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "hal/error.hpp"
#include "hal_registry/registry.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<std::string> comparisons_of(const std::string& text, const std::string& name) {
  const std::string quoted = "\"" + name + "\"";
  const std::regex compare("(==|!=)\\s*" + quoted + "|" + quoted + "\\s*(==|!=)|IsMember\\(\\{[^}]*" + quoted);
  std::vector<std::string> found;
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (std::regex_search(line, compare)) found.push_back(std::to_string(number) + ": " + line);
  }
  return found;
}

}  // namespace

TEST_CASE("no source file compares a string with a backend's name outside the registry") {
  const fs::path root = ASVGF_SOURCE_DIR;
  REQUIRE(!hal::registry::backends().empty());
  int files = 0;
  for (const char* folder : {"apps", "pipeline", "include", "hal", "hal_vulkan", "hal_gl", "tests", "tools"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
      const auto ext = entry.path().extension();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
      if (entry.path().filename() == "backend_entry.cpp" || entry.path().filename() == "backend_names_test.cpp")
        continue;
      std::ifstream in(entry.path());
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      ++files;
      for (const auto& backend : hal::registry::backends())
        for (const auto& line : comparisons_of(text, backend.name))
          FAIL_CHECK(entry.path().lexically_relative(root).string() << ":" << line);
    }
  }
  CHECK(files > 100);
}

TEST_CASE("the name check finds a comparison as it was written before the registry") {
  CHECK(comparisons_of("  if (backend == \"gl\" || backend == \"gles\") {", "gl").size() == 1);
  CHECK(comparisons_of("  if (\"vulkan\" != chosen) return;", "vulkan").size() == 1);
  CHECK(comparisons_of("->check(CLI::IsMember({\"vulkan\", \"gl\", \"gles\"}));", "gles").size() == 1);
  CHECK(comparisons_of("  return flavour == hal::gl::Flavour::Gl ? \"gl\" : \"gles\";", "gl").empty());
}

TEST_CASE("the registry names its backends once each, the default first") {
  const auto& all = hal::registry::backends();
  for (std::size_t i = 0; i < all.size(); ++i) {
    CAPTURE(all[i].name);
    CHECK(!all[i].name.empty());
    CHECK(static_cast<bool>(all[i].open));
    for (std::size_t j = i + 1; j < all.size(); ++j) CHECK(all[i].name != all[j].name);
  }
  CHECK(&hal::registry::default_backend() == &all.front());
  CHECK_THROWS_WITH_AS((void)hal::registry::backend("metal"), doctest::Contains("'metal' is not one of"), hal::Error);
}
