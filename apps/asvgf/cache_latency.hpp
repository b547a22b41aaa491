// How long one load takes when each load's address is the last load's value, for chains of growing
// size, through a storage buffer and through a sampled image: where the time steps up, a cache
// ends. `asvgf bench --cache-latency` prints it, so that a porter can see whether a backend's buffer
// loads get the cache that another backend's (or its own image loads) get (hal/PORTING.md).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "hal/device.hpp"

namespace asvgf::cli {

struct CacheLatency {
  std::uint64_t working_set = 0;    // bytes: the chain's elements are a 128-byte cache line each
  std::optional<double> buffer_ns;  // one dependent load from a storage buffer (median)
  std::optional<double> image_ns;   // one dependent texelFetch (empty: taller than the device allows)
};

// One row per working set; empty when the device has no timestamps. Throws when a chain's walk on
// the device ends elsewhere than the same walk on the host (a backend that loads wrong values).
std::vector<CacheLatency> measure_cache_latency(hal::Device& device);

}  // namespace asvgf::cli
