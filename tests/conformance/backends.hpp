// The HAL conformance suite runs on every backend registered here: the backend registry's backends
// an executable names (backend_registry.cpp) and the recording HAL (backend_record.cpp).
#pragma once

#include <doctest/doctest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hal/hal.hpp"
#include "hal/layer.hpp"
#include "hal/validate.hpp"

namespace conformance {

struct Backend {
  std::string name;
  // Creates a device. Everything the backend's checker reports (Vulkan validation messages, ...)
  // is appended to `messages`; a conformant run leaves it empty.
  std::function<std::unique_ptr<hal::Device>(std::vector<std::string>& messages)> create;
  // False for backends that record but do not execute (reads return no results): tests that
  // check computed values skip them, tests of ordering still run.
  bool executes = true;
  // Called before the device is destroyed, to pull reports the backend keeps on the device.
  std::function<void(hal::Device& device, std::vector<std::string>& messages)> collect;
};

std::vector<Backend>& backends();

struct Register {
  explicit Register(Backend backend) { backends().push_back(std::move(backend)); }
};

// A device of one backend, behind the validation layer (hal/validate.hpp), for the length of a
// test; on destruction it destroys the device and
// fails the test on any message the backend reported.
class TestDevice {
 public:
  explicit TestDevice(const Backend& backend) : backend_(backend.name), collect_(backend.collect) {
    device_ = hal::validate::wrap(backend.create(messages_));
  }
  ~TestDevice() {
    if (collect_ && device_) collect_(hal::backend_of(*device_), messages_);
    device_.reset();
    for (const auto& m : messages_) FAIL_CHECK(backend_ << " reported: " << m);
  }
  TestDevice(const TestDevice&) = delete;
  TestDevice& operator=(const TestDevice&) = delete;
  hal::Device& operator*() { return *device_; }
  hal::Device* operator->() { return device_.get(); }
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  std::string backend_;
  std::function<void(hal::Device&, std::vector<std::string>&)> collect_;
  std::vector<std::string> messages_;
  std::unique_ptr<hal::Device> device_;
};

// Runs `body(device)` once per registered backend that executes, each in its own subcase.
template <typename F>
void for_each_backend(F&& body) {
  REQUIRE_MESSAGE(!backends().empty(), "no HAL backend is registered in this test executable");
  for (const auto& backend : backends()) {
    if (!backend.executes) continue;
    SUBCASE(backend.name.c_str()) {
      TestDevice device(backend);
      body(*device);
    }
  }
}

// Runs `body(device, executes)` on every registered backend, executing or not.
template <typename F>
void for_every_backend(F&& body) {
  REQUIRE_MESSAGE(!backends().empty(), "no HAL backend is registered in this test executable");
  for (const auto& backend : backends()) {
    SUBCASE(backend.name.c_str()) {
      TestDevice device(backend);
      body(*device, backend.executes);
    }
  }
}

}  // namespace conformance
