// Vulkan device creation: adapter choice, capabilities, validation wiring.
#include <cstdlib>
#include <string>

#include "env_guard.hpp"
#include "validated_device.hpp"

using hal::vulkan::AdapterReport;

namespace {

AdapterReport fake(std::uint32_t index, const char* name, hal::DeviceType type) {
  AdapterReport a;
  a.index = index;
  a.info.name = name;
  a.info.type = type;
  a.info.api_version = "Vulkan 1.3.280";
  return a;
}

}  // namespace

TEST_CASE("vulkan device: adapter selection by index, name and type") {
  const std::vector<AdapterReport> adapters = {fake(0, "llvmpipe (LLVM 15.0.6, 256 bits)", hal::DeviceType::Cpu),
                                               fake(1, "Intel(R) UHD 770", hal::DeviceType::IntegratedGpu),
                                               fake(2, "NVIDIA H200", hal::DeviceType::DiscreteGpu)};
  CHECK(hal::vulkan::select_adapter(adapters, "") == 2);  // discrete first
  CHECK(hal::vulkan::select_adapter(adapters, "0") == 0);
  CHECK(hal::vulkan::select_adapter(adapters, "LLVMpipe") == 0);
  CHECK(hal::vulkan::select_adapter(adapters, "h200") == 2);
  CHECK(hal::vulkan::select_adapter({adapters[0], adapters[1]}, "") == 1);  // integrated before CPU
  for (const char* missing : {"7", "radeon"}) {
    try {
      hal::vulkan::select_adapter(adapters, missing);
      FAIL_CHECK("expected NoDevice for " << missing);
    } catch (const hal::Error& e) {
      CHECK(e.kind() == hal::ErrorKind::NoDevice);
      CHECK(e.object() == missing);
      const std::string what = e.what();
      CHECK(what.find("NVIDIA H200") != std::string::npos);  // lists what exists
      CHECK(what.find("llvmpipe") != std::string::npos);
    }
  }
}

TEST_CASE("vulkan device: a missing adapter is an error naming it and listing the others") {
  hal::vulkan::DeviceOptions options;
  options.adapter = "no-such-gpu";
  try {
    ValidatedDevice device(options);
    FAIL_CHECK("expected NoDevice");
  } catch (const hal::Error& e) {
    CHECK(e.kind() == hal::ErrorKind::NoDevice);
    const std::string what = e.what();
    CHECK(what.find("no-such-gpu") != std::string::npos);
    CHECK(what.find(hal::vulkan::list_adapters().front().info.name) != std::string::npos);
  }
}

TEST_CASE("vulkan device: ASVGF_DEVICE picks the adapter when the option is empty") {
  EnvGuard guard(hal::vulkan::kAdapterEnvVar);
  const auto adapters = hal::vulkan::list_adapters();
  setenv(hal::vulkan::kAdapterEnvVar, std::to_string(adapters.back().index).c_str(), 1);
  {
    ValidatedDevice device;
    CHECK(device->adapter().name == adapters.back().info.name);
  }
  setenv(hal::vulkan::kAdapterEnvVar, "definitely-not-a-gpu", 1);
  try {
    ValidatedDevice device;
    FAIL_CHECK("expected NoDevice");
  } catch (const hal::Error& e) {
    CHECK(e.kind() == hal::ErrorKind::NoDevice);
    CHECK(e.object() == "definitely-not-a-gpu");
  }
  // An explicit option wins over the environment.
  hal::vulkan::DeviceOptions options;
  options.adapter = "0";
  ValidatedDevice device(options);
  CHECK(device->adapter().name == adapters.front().info.name);
}

TEST_CASE("vulkan device: require_ray_query follows the adapter's capability") {
  for (const auto& adapter : hal::vulkan::list_adapters()) {
    CAPTURE(adapter.info.name);
    hal::vulkan::DeviceOptions options;
    options.adapter = std::to_string(adapter.index);
    options.require_ray_query = true;
    if (adapter.capabilities.ray_query) {
      ValidatedDevice device(options);
      CHECK(device->capabilities().ray_query);
      CHECK(device->capabilities().acceleration_structures);
    } else {
      try {
        ValidatedDevice device(options);
        FAIL_CHECK("expected Unsupported");
      } catch (const hal::Error& e) {
        CHECK(e.kind() == hal::ErrorKind::Unsupported);
        CHECK(std::string(e.what()).find("ray quer") != std::string::npos);
      }
      // Without the requirement the same adapter gives a usable device without ray queries.
      options.require_ray_query = false;
      ValidatedDevice device(options);
      CHECK_FALSE(device->capabilities().ray_query);
    }
  }
}

TEST_CASE("vulkan device: capabilities and adapter info are filled in") {
  ValidatedDevice device;
  const auto& caps = device->capabilities();
  const auto& info = device->adapter();
  CHECK_FALSE(info.name.empty());
  CHECK(info.api_version.rfind("Vulkan 1.", 0) == 0);
  CHECK(caps.max_image_dimension >= 4096);
  CHECK(caps.max_storage_buffer_range >= (1u << 27) / 1024);
  CHECK(caps.max_buffer_size >= caps.max_storage_buffer_range);
  if (info.name.find("llvmpipe") != std::string::npos) {
    // Lavapipe (Mesa 25) has all of these; the suite relies on them.
    CHECK(caps.ray_query);
    CHECK(caps.acceleration_structures);
    CHECK(caps.timestamps);
    CHECK(caps.subgroup_size > 0);
  }
}

TEST_CASE("vulkan device: synchronization validation reports a missing barrier") {
  // The harness is only useful if it hears hazards: two copies into one buffer, no barrier between.
  std::vector<std::string> messages;
  {
    hal::vulkan::DeviceOptions options;
    options.validation = true;
    options.on_validation_message = [&](const std::string& m) { messages.push_back(m); };
    auto device = hal::vulkan::create_device(options);
    const auto usage = hal::BufferUsage::CopySrc | hal::BufferUsage::CopyDst;
    const auto a = device->create_buffer({"hazard a", 1024, usage});
    const auto b = device->create_buffer({"hazard b", 1024, usage});
    auto cmd = device->create_command_list("hazard");
    cmd->barrier({a, hal::State::Undefined, hal::State::CopySrc});
    cmd->barrier({b, hal::State::Undefined, hal::State::CopyDst});
    cmd->copy_buffer({a, b, 0, 0, 1024});
    cmd->copy_buffer({a, b, 0, 0, 1024});  // write-after-write without a barrier
    device->submit(*cmd);
    device->wait();
  }
  REQUIRE_FALSE(messages.empty());
  CHECK(messages.front().find("SYNC-HAZARD-WRITE-AFTER-WRITE") != std::string::npos);
}
