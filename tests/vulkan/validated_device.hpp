// A Vulkan device with validation and synchronization validation whose messages fail the test.
#pragma once

#include <doctest/doctest.h>

#include <memory>
#include <string>
#include <vector>

#include "hal/hal.hpp"
#include "hal/validate.hpp"
#include "hal_vulkan/vulkan.hpp"

struct ValidatedDevice {
  std::vector<std::string> messages;
  std::unique_ptr<hal::Device> device;

  explicit ValidatedDevice(hal::vulkan::DeviceOptions options = {}) {
    options.validation = true;
    options.on_validation_message = [this](const std::string& m) { messages.push_back(m); };
    device = hal::validate::wrap(hal::vulkan::create_device(options));
  }
  ~ValidatedDevice() {
    device.reset();
    for (const auto& m : messages) FAIL_CHECK("validation: " << m);
  }
  ValidatedDevice(const ValidatedDevice&) = delete;
  ValidatedDevice& operator=(const ValidatedDevice&) = delete;
  hal::Device* operator->() { return device.get(); }
  hal::Device& operator*() { return *device; }
};
