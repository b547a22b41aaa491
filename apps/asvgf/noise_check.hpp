// Whether a sequence's noise repeats from frame to frame, judged from the data: with the renderer's
// seed the same every frame (Blender's default: Cycles' Seed without its clock icon), a pixel where
// nothing moved gets exactly the same samples, so its colour is bit-identical to the previous
// frame's. SVGF and A-SVGF estimate the noise from how a pixel changes over time: repeated noise
// has no variance, so the filter leaves it as it is and the "denoised" frames stay noisy.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace asvgf::cli {

struct RepeatedNoiseCheck {
  std::uint32_t still_pixels = 0;  // lit surface pixels that did not move (motion under 0.01 px)
  std::uint32_t identical = 0;     // of those, colour bit-identical to the previous frame's
  std::optional<std::string> problem;
};

// color, previous_color: RGBA floats; depth, previous_depth: linear depth in R; motion: RGBA floats
// with the vector in RG in the denoiser's convention, empty when nothing moves. Fewer than 64 still
// pixels give no verdict; more than half of them identical is the problem.
RepeatedNoiseCheck check_repeated_noise(std::span<const float> previous_color, std::span<const float> color,
                                        std::span<const float> previous_depth, std::span<const float> depth,
                                        std::span<const float> motion, std::uint32_t w, std::uint32_t h);

}  // namespace asvgf::cli
