#include "noise_check.hpp"

#include <cmath>

#include "asvgf/denoiser.hpp"

namespace asvgf::cli {
namespace {

constexpr std::uint32_t kMinStill = 64;
// With a new seed each frame, two Monte Carlo estimates of a lit pixel are bit-identical only where
// the light is not sampled at all (an emitter seen directly): far from half the still pixels.
constexpr double kRepeatedShare = 0.5;
constexpr double kStillMotion = 0.01;  // pixels
constexpr double kSameSurface = 0.01;  // relative depth: a jittered sample position moves it a little

}  // namespace

RepeatedNoiseCheck check_repeated_noise(std::span<const float> previous_color, std::span<const float> color,
                                        std::span<const float> previous_depth, std::span<const float> depth,
                                        std::span<const float> motion, std::uint32_t w, std::uint32_t h) {
  RepeatedNoiseCheck out;
  for (std::size_t i = 0; i < std::size_t(w) * h * 4; i += 4) {
    const double z = depth[i], zp = previous_depth[i];
    if (asvgf::is_background_depth(z) || asvgf::is_background_depth(zp) || std::abs(z - zp) > kSameSurface * z)
      continue;
    if (!motion.empty() && !(std::hypot(motion[i], motion[i + 1]) < kStillMotion)) continue;
    const float r = color[i], g = color[i + 1], b = color[i + 2];
    if (!(std::isfinite(r) && std::isfinite(g) && std::isfinite(b)) || r + g + b <= 0.0f) continue;  // unlit
    ++out.still_pixels;
    if (r == previous_color[i] && g == previous_color[i + 1] && b == previous_color[i + 2]) ++out.identical;
  }
  if (out.still_pixels >= kMinStill && out.identical > kRepeatedShare * out.still_pixels) {
    const int percent = int(std::lround(100.0 * out.identical / out.still_pixels));
    out.problem = "the colour is bit-identical to the previous frame's at " + std::to_string(percent) + "% of the " +
                  std::to_string(out.still_pixels) +
                  " lit pixels that did not move: the noise repeats, as when the renderer's seed is the same "
                  "every frame (Cycles: Render Properties > Sampling > Seed, the clock icon animates it). The "
                  "filter estimates the noise from how each pixel changes over time, so repeated noise would be "
                  "left as it is";
  }
  return out;
}

}  // namespace asvgf::cli
