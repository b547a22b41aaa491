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

TEST_CASE("conformance: a 1 TiB buffer is out of memory") {
  for_each_backend([](hal::Device& device) {
    check_error([&] { device.create_buffer({"terabyte", std::uint64_t{1} << 40, hal::BufferUsage::Storage}); },
                ErrorKind::OutOfMemory, "terabyte");
    // The device stays usable.
    const auto small = device.create_buffer({"after oom", 256, hal::BufferUsage::Storage});
    device.destroy(small);
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
