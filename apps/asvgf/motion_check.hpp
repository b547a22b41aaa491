// Whether a frame's motion vectors follow the denoiser's convention (previous minus current
// position, in pixels), judged from the data alone: following the vectors from a pixel into the
// previous frame should land on the same surface, so the previous frame's depth there should match
// this pixel's. The vectors as given are compared with the usual mistakes (the opposite sign,
// UV units instead of pixels, both); when a mistake fits the depths clearly better, it is named.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "asvgf/denoiser.hpp"

namespace asvgf::cli {

struct MotionFit {
  std::string convention;  // "as given", "negated", "y-flipped", "x-flipped", "in UV units", ...
  double consistent = 0;   // fraction of the moving pixels whose reprojected depth matches
};
struct MotionCheck {
  std::uint32_t moving_pixels = 0;  // pixels on a surface whose vector moves them by >= 0.5 px
  MotionFit as_given, best;
  // Set when another convention fits clearly better: says which and what the denoiser expects.
  std::optional<std::string> problem;
};

// depth, previous_depth: RGBA floats with linear depth in R (background: asvgf::is_background_depth);
// motion: RGBA floats with the vector in RG, already converted from `given` to the denoiser's
// convention; a problem names the setting that reads them right. Too few moving pixels (under
// 32) give no verdict.
MotionCheck check_motion(std::span<const float> previous_depth, std::span<const float> depth,
                         std::span<const float> motion, std::uint32_t width, std::uint32_t height,
                         const MotionConvention& given = {});

}  // namespace asvgf::cli
