// hal/fault.hpp: fault injection for tests. wrap() puts a layer in front of any backend that makes
// the n-th call of one kind fail the way a backend fails: buffer or image creation with
// OutOfMemory, pipeline creation with Unsupported, submit or wait with DeviceLost (after which every
// call but destroy fails too, as on a lost device), an upload or a readback with Backend. It also
// counts the calls of each kind, so that a test can sweep n over all of them.
//
// The apps take a plan from the environment (ASVGF_FAULT, see from_environment) and put this layer
// under the validation layer: validate::wrap(fault::wrap(backend, plan)).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "hal/device.hpp"

namespace hal::fault {

enum class Kind : std::uint8_t { Buffer, Image, Pipeline, Submit, Wait, Upload, Readback };
inline constexpr std::array kAllKinds = {Kind::Buffer, Kind::Image,  Kind::Pipeline, Kind::Submit,
                                         Kind::Wait,   Kind::Upload, Kind::Readback};
std::string_view to_string(Kind kind);

struct Plan {
  Kind kind = Kind::Buffer;
  std::uint32_t nth = 0;  // 1-based; 0 injects nothing (counting only)
};

// Calls of each kind a wrapped device has seen, in kAllKinds order.
using Counts = std::array<std::uint32_t, kAllKinds.size()>;

// A device that forwards to `inner`, failing as `plan` says. With `report_counts`, its destructor
// prints "fault counts: buffer N, image N, ..." to stderr (what a sweep reads to know its range).
std::unique_ptr<Device> wrap(std::unique_ptr<Device> inner, Plan plan, bool report_counts = false);

// ASVGF_FAULT: "<kind>:<n>" (kind: buffer, image, pipeline, submit, wait, upload, readback) fails
// the n-th call of that kind; "count" injects nothing and reports the counts. Empty or unset:
// nullopt. Throws std::invalid_argument naming the variable for anything else.
struct EnvironmentPlan {
  Plan plan;
  bool report_counts = false;
};
std::optional<EnvironmentPlan> from_environment();

}  // namespace hal::fault
