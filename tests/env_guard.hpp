// Test helper: sets an environment variable for the rest of a scope and restores it (or its
// absence) when the scope ends.
#pragma once

#include <cstdlib>
#include <string>

struct EnvGuard {
  std::string name;
  std::string old;
  bool had;
  explicit EnvGuard(const char* n) : name(n), had(std::getenv(n) != nullptr) {
    if (had) old = std::getenv(n);
  }
  EnvGuard(const char* n, const char* value) : EnvGuard(n) { setenv(n, value, 1); }
  ~EnvGuard() {
    if (had)
      setenv(name.c_str(), old.c_str(), 1);
    else
      unsetenv(name.c_str());
  }
  EnvGuard(const EnvGuard&) = delete;
  EnvGuard& operator=(const EnvGuard&) = delete;
};
