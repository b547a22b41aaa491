// Registers the backend registry's backends named in ASVGF_CONFORMANCE_BACKENDS (a comma list set
// per test executable in CMakeLists.txt), each with its validation on (Vulkan: validation and
// synchronization validation; OpenGL: debug-output errors): every message fails the test.
#include <sstream>
#include <string>
#include <vector>

#include "backends.hpp"
#include "hal_registry/registry.hpp"

namespace {

std::vector<std::string> listed_names() {
  std::vector<std::string> names;
  std::stringstream list(ASVGF_CONFORMANCE_BACKENDS);
  for (std::string name; std::getline(list, name, ',');) names.push_back(name);
  return names;
}

const bool registered = [] {
  for (const auto& name : listed_names())
    for (const auto& backend : hal::registry::backends())
      if (backend.name == name)
        conformance::backends().push_back({name, [&backend](std::vector<std::string>& messages) {
                                             hal::registry::OpenOptions options;
                                             options.validation = true;
                                             options.on_message = [&messages](const std::string& m) {
                                               messages.push_back(m);
                                             };
                                             return backend.open(options);
                                           }});
  return true;
}();

TEST_CASE("every backend this executable names is in the registry") {
  CHECK(registered);
  for (const auto& name : listed_names()) {
    CAPTURE(name);
    CHECK_NOTHROW((void)hal::registry::backend(name));
  }
}

}  // namespace
