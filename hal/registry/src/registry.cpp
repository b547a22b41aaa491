#include "hal_registry/registry.hpp"

#include "hal/error.hpp"

namespace hal::registry {

const Backend& backend(std::string_view name) {
  for (const auto& b : backends())
    if (b.name == name) return b;
  throw Error(ErrorKind::InvalidUsage, "backend", "'" + std::string(name) + "' is not one of " + names());
}

const Backend& default_backend() {
  if (backends().empty()) throw Error(ErrorKind::NoDevice, "backend", "this build has no HAL backend");
  return backends().front();
}

std::string names(std::string_view separator) {
  std::string out;
  for (const auto& b : backends()) out += (out.empty() ? "" : std::string(separator)) + b.name;
  return out;
}

}  // namespace hal::registry
