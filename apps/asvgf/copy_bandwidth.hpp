// The memory bandwidth a device reaches copying a storage buffer with a compute pass (16-byte loads
// and stores, as the frame's passes move memory), timed with timestamps: what `asvgf bench` divides
// each pass's bytes by to get the pass's floor.
#pragma once

#include <cstdint>
#include <optional>

#include "hal/device.hpp"

namespace asvgf::cli {

struct CopyBandwidth {
  std::uint64_t bytes = 0;      // copied per repetition (each is read once and written once)
  double median_ms = 0.0;       // one copy
  double bytes_per_second = 0;  // 2 * bytes / median time
};

// Copies `bytes` between two buffers `repeats` times back to back, each copy its own timer region;
// empty when the device has no timestamps.
std::optional<CopyBandwidth> measure_copy_bandwidth(hal::Device& device, std::uint64_t bytes, int repeats);

}  // namespace asvgf::cli
