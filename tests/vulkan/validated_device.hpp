// The device a GPU test runs on, behind the HAL validation layer, whose backend messages fail the
// test: by default Vulkan with validation and synchronization validation (the Vulkan tests pass
// their own hal::vulkan::DeviceOptions); in executables compiled with ASVGF_TEST_BACKEND="<name>",
// the backend registry's backend of that name with its validation on (OpenGL: debug-output
// errors); with ASVGF_TEST_BACKEND_WEBGPU, the shaders' WGSL in Dawn through the test-only backend
// in tests/wgsl, which is not in the registry. Tests written once against it run on each backend
// they are compiled for.
#pragma once

#include <doctest/doctest.h>

#include <memory>
#include <string>
#include <vector>

#include "hal/hal.hpp"
#include "hal/validate.hpp"
#include "hal_vulkan/vulkan.hpp"
#if defined(ASVGF_TEST_BACKEND)
#include "hal_registry/registry.hpp"
#endif
#if defined(ASVGF_TEST_BACKEND_WEBGPU)
#include "dawn_device.hpp"
#endif

struct ValidatedDevice {
  std::vector<std::string> messages;
  std::unique_ptr<hal::Device> device;

  explicit ValidatedDevice(hal::vulkan::DeviceOptions options = {}) {
#if defined(ASVGF_TEST_BACKEND_WEBGPU)
    (void)options;
    device = hal::validate::wrap(hal::dawn_node::create_device(
        hal::dawn_node::build_options([this](const std::string& m) { messages.push_back(m); })));
#elif defined(ASVGF_TEST_BACKEND)
    (void)options;
    hal::registry::OpenOptions open;
    open.validation = true;
    open.on_message = [this](const std::string& m) { messages.push_back(m); };
    device = hal::validate::wrap(hal::registry::backend(ASVGF_TEST_BACKEND).open(open));
#else
    options.validation = true;
    options.on_validation_message = [this](const std::string& m) { messages.push_back(m); };
    device = hal::validate::wrap(hal::vulkan::create_device(options));
#endif
  }
  ~ValidatedDevice() {
    device.reset();
    for (const auto& m : messages) FAIL_CHECK("validation: " << m);
  }
  ValidatedDevice(const ValidatedDevice&) = delete;
  ValidatedDevice& operator=(const ValidatedDevice&) = delete;
  hal::Device* operator->() {
    return device.get();
  }
  hal::Device& operator*() {
    return *device;
  }
};
