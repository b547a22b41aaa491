// HAL value types: format table consistency, error messages naming object and cause.
#include <doctest/doctest.h>

#include "hal/error.hpp"
#include "hal/types.hpp"

TEST_CASE("every exposed format has a size, channel count and a name that round-trips") {
  for (hal::Format f : hal::kAllFormats) {
    CAPTURE(hal::format_name(f));
    CHECK(hal::format_size(f) > 0);
    CHECK(hal::format_channels(f) >= 1);
    CHECK(hal::format_size(f) % hal::format_channels(f) == 0);
    CHECK(hal::format_from_name(hal::format_name(f)) == f);
  }
  CHECK(hal::format_size(hal::Format::RGBA16F) == 8);
  CHECK(hal::format_size(hal::Format::RGBA32F) == 16);
  CHECK(hal::format_from_name("rgb9e5") == hal::Format::Undefined);
}

TEST_CASE("hal::Error names the kind, the object and the cause") {
  const hal::Error e(hal::ErrorKind::OutOfMemory, "history.color", "no memory type can hold 64 GiB");
  const std::string what = e.what();
  CHECK(what.find("out of memory") != std::string::npos);
  CHECK(what.find("'history.color'") != std::string::npos);
  CHECK(what.find("64 GiB") != std::string::npos);
  CHECK(e.kind() == hal::ErrorKind::OutOfMemory);
  CHECK(e.object() == "history.color");
}
