// Whether `--color` holds radiance or radiance already divided by the albedo, judged from the data:
// radiance carries the albedo's colour (a red wall is red), demodulated colour carries only the
// light's. Across the surface pixels whose albedo is coloured, the correlation between the colour's
// and the albedo's chromaticity (log R/G and log B/G) is high for radiance and low for demodulated
// colour; where it clearly contradicts what the options declare, the check names the option.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace asvgf::cli {

struct ColorKindCheck {
  std::uint32_t pixels = 0;  // surface pixels with a coloured albedo and a positive colour
  double correlation = 0;    // of the colour's chromaticity with the albedo's
  std::optional<std::string> problem;
};

// color, albedo, depth: RGBA floats (depth in R); `declared_radiance`: what the options say.
// Fewer than 64 usable pixels give no verdict.
ColorKindCheck check_color_kind(std::span<const float> color, std::span<const float> albedo,
                                std::span<const float> depth, bool declared_radiance);

}  // namespace asvgf::cli
