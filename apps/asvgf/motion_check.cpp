#include "motion_check.hpp"

#include <cmath>
#include <cstdio>

namespace asvgf::cli {
namespace {

// A reprojected depth within this fraction of the current one is the same surface (the A-SVGF
// temporal pass allows 2% plus the depth gradient; a frame's own motion along the view axis adds
// to that).
constexpr double kSameSurface = 0.05;
constexpr std::uint32_t kMinMoving = 32;

struct Candidate {
  const char* name;
  double sign;
  bool uv;
};
constexpr Candidate kCandidates[] = {
    {"as given", 1, false}, {"negated", -1, false}, {"in UV units", 1, true}, {"negated, in UV units", -1, true}};

}  // namespace

MotionCheck check_motion(std::span<const float> previous_depth, std::span<const float> depth,
                         std::span<const float> motion, std::uint32_t w, std::uint32_t h) {
  MotionCheck out;
  double consistent[4] = {0, 0, 0, 0};
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) {
      const std::size_t i = (std::size_t(y) * w + x) * 4;
      const double z = depth[i], mx = motion[i], my = motion[i + 1];
      if (!(z > 0) || !std::isfinite(z)) continue;
      // Moving in the convention as given, or as UV units: candidates are judged on the same pixels.
      if (std::hypot(mx, my) < 0.5 && std::hypot(mx * w, my * h) < 0.5) continue;
      if (std::hypot(mx, my) > 1e5) continue;  // "was off screen"
      ++out.moving_pixels;
      for (int c = 0; c < 4; ++c) {
        const Candidate& k = kCandidates[c];
        const double dx = k.sign * (k.uv ? mx * w : mx), dy = k.sign * (k.uv ? my * h : my);
        const double px = std::floor(x + 0.5 + dx), py = std::floor(y + 0.5 + dy);
        if (px < 0 || py < 0 || px >= w || py >= h) continue;
        const double zp = previous_depth[(std::size_t(py) * w + std::size_t(px)) * 4];
        if (zp > 0 && std::abs(zp - z) <= kSameSurface * z) consistent[c] += 1;
      }
    }
  if (out.moving_pixels == 0) return out;
  int best = 0;
  for (int c = 0; c < 4; ++c) {
    consistent[c] /= out.moving_pixels;
    if (consistent[c] > consistent[best]) best = c;
  }
  out.as_given = {kCandidates[0].name, consistent[0]};
  out.best = {kCandidates[best].name, consistent[best]};
  if (out.moving_pixels >= kMinMoving && best != 0 && consistent[best] >= 0.6 &&
      consistent[best] > consistent[0] + 0.25) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "the vectors look %s: reprojected that way %.0f%% of %u moving pixels land on the same surface in "
                  "the previous frame, as given %.0f%%. The denoiser needs previous minus current position, in pixels",
                  kCandidates[best].name, 100 * consistent[best], out.moving_pixels, 100 * consistent[0]);
    out.problem = text;
  }
  return out;
}

}  // namespace asvgf::cli
