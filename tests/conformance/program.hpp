// A small multi-dispatch program that every backend must accept: on an executing backend it
// gives the expected values with no validation message, on the recording HAL no report.
#pragma once

#include <vector>

#include "hal/hal.hpp"

namespace conformance {

// Runs: upload → scale (×2 +1) → copy → scale (×0.5 −3) in place on a second buffer → readback.
// Returns the final values (zeros on a backend that does not execute).
std::vector<float> run_multi_dispatch_program(hal::Device& device, const std::vector<float>& input);

}  // namespace conformance
