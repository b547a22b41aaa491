// Failure paths: clear hal::Error kinds that name the object, and no crash.
#include <string>

#include "backends.hpp"

using namespace conformance;
using hal::ErrorKind;

namespace {

template <typename F>
void check_error(F&& call, ErrorKind kind, const std::string& object) {
  try {
    call();
    FAIL_CHECK("expected hal::Error(" << hal::to_string(kind) << ") about '" << object << "'");
  } catch (const hal::Error& e) {
    CHECK_MESSAGE(e.kind() == kind, e.what());
    CHECK_MESSAGE(e.object() == object, e.what());
    CHECK(std::string(e.what()).find(object) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("conformance: zero and absurd sizes are invalid descriptors") {
  for_each_backend([](hal::Device& device) {
    check_error([&] { device.create_buffer({"empty buffer", 0, hal::BufferUsage::Storage}); },
                ErrorKind::InvalidDescriptor, "empty buffer");
    check_error([&] { device.create_buffer({"huge buffer", ~std::uint64_t{0}, hal::BufferUsage::Storage}); },
                ErrorKind::InvalidDescriptor, "huge buffer");
    check_error([&] { device.create_image({"flat image", 16, 0, hal::Format::RGBA16F}); },
                ErrorKind::InvalidDescriptor, "flat image");
    check_error([&] { device.create_image({"vast image", 1u << 30, 4, hal::Format::RGBA16F}); },
                ErrorKind::InvalidDescriptor, "vast image");
    check_error([&] { device.create_image({"formatless", 4, 4, hal::Format::Undefined}); },
                ErrorKind::InvalidDescriptor, "formatless");
    check_error([&] { device.create_image({"alien format", 4, 4, static_cast<hal::Format>(200)}); },
                ErrorKind::InvalidDescriptor, "alien format");
    check_error([&] { device.create_timer_queries({"no regions", 0}); }, ErrorKind::InvalidDescriptor, "no regions");
  });
}

TEST_CASE("conformance: a 1 TiB buffer is out of memory") {
  for_each_backend([](hal::Device& device) {
    check_error([&] { device.create_buffer({"terabyte", std::uint64_t{1} << 40, hal::BufferUsage::Storage}); },
                ErrorKind::OutOfMemory, "terabyte");
    // The device stays usable.
    const auto small = device.create_buffer({"after oom", 256, hal::BufferUsage::Storage});
    device.destroy(small);
  });
}

TEST_CASE("conformance: destroyed handles are reported") {
  for_each_backend([](hal::Device& device) {
    const auto buffer = device.create_buffer({"short lived", 64, hal::BufferUsage::CopyDst});
    device.destroy(buffer);
    try {
      device.destroy(buffer);
      FAIL_CHECK("destroying twice should throw");
    } catch (const hal::Error& e) {
      CHECK(e.kind() == ErrorKind::InvalidHandle);
    }
    try {
      std::vector<std::byte> data(4);
      device.upload_buffer(buffer, 0, data);
      FAIL_CHECK("using a destroyed buffer should throw");
    } catch (const hal::Error& e) {
      CHECK(e.kind() == ErrorKind::InvalidHandle);
    }
  });
}

TEST_CASE("conformance: unsupported formats are reported as Unsupported naming the image") {
  for_each_backend([](hal::Device& device) {
    // Whatever the device lacks must come back as Unsupported; what it has must work.
    const auto usage = hal::ImageUsage::Sampled | hal::ImageUsage::Storage | hal::ImageUsage::CopySrc |
                       hal::ImageUsage::CopyDst;
    int supported = 0;
    for (const hal::Format format : hal::kAllFormats) {
      const std::string name = "probe " + std::string(hal::format_name(format));
      try {
        device.destroy(device.create_image({name, 8, 8, format, usage}));
        ++supported;
      } catch (const hal::Error& e) {
        CHECK_MESSAGE(e.kind() == ErrorKind::Unsupported, e.what());
        CHECK(e.object() == name);
        CHECK(std::string(e.what()).find(hal::format_name(format)) != std::string::npos);
      }
    }
    CHECK(supported > 0);
  });
}
