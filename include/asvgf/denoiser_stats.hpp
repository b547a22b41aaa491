// asvgf/denoiser_stats.hpp: what a frame reports besides its images: the GPU time of each pass and
// the samples the denoiser sanitised. One type each, used by the public API (asvgf::Denoiser), the
// render graph and our renderer alike.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace asvgf {

struct PassTime {
  std::string pass;
  std::optional<double> gpu_ms;  // empty when the device has no timestamps
};

// Samples dropped (NaN, Inf) or clamped to the fp16 maximum (or at it) before the histories, and output pixels
// written as 0 because they were not finite.
struct SanitisedCounts {
  std::uint32_t nan_samples = 0, inf_samples = 0, clamped_samples = 0, zeroed_outputs = 0;
};

}  // namespace asvgf
