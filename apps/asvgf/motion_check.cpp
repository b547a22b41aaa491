#include "motion_check.hpp"

#include <cmath>
#include <cstdio>

#include "asvgf/denoiser.hpp"
#include "input_conventions.hpp"

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
  bool flip_y;
  bool uv;
};
constexpr Candidate kCandidates[] = {{"as given", 1, false, false},
                                     {"negated", -1, false, false},
                                     {"y-flipped", 1, true, false},
                                     {"x-flipped", -1, true, false},
                                     {"in UV units", 1, false, true},
                                     {"negated, in UV units", -1, false, true},
                                     {"y-flipped, in UV units", 1, true, true},
                                     {"x-flipped, in UV units", -1, true, true}};
constexpr int kCount = sizeof kCandidates / sizeof kCandidates[0];

}  // namespace

MotionCheck check_motion(std::span<const float> previous_depth, std::span<const float> depth,
                         std::span<const float> motion, std::uint32_t w, std::uint32_t h,
                         const MotionConvention& given) {
  MotionCheck out;
  double consistent[kCount] = {};
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) {
      const std::size_t i = (std::size_t(y) * w + x) * 4;
      const double z = depth[i], mx = motion[i], my = motion[i + 1];
      if (asvgf::is_background_depth(z)) continue;
      // Moving in the convention as given, or as UV units: candidates are judged on the same pixels.
      if (std::hypot(mx, my) < 0.5 && std::hypot(mx * w, my * h) < 0.5) continue;
      if (std::hypot(mx, my) > 1e5) continue;  // "was off screen"
      ++out.moving_pixels;
      for (int c = 0; c < kCount; ++c) {
        const Candidate& k = kCandidates[c];
        const double dx = k.sign * (k.uv ? mx * w : mx), dy = k.sign * (k.flip_y ? -1 : 1) * (k.uv ? my * h : my);
        const double px = std::floor(x + 0.5 + dx), py = std::floor(y + 0.5 + dy);
        if (px < 0 || py < 0 || px >= w || py >= h) continue;
        const double zp = previous_depth[(std::size_t(py) * w + std::size_t(px)) * 4];
        if (!asvgf::is_background_depth(zp) && std::abs(zp - z) <= kSameSurface * z) consistent[c] += 1;
      }
    }
  if (out.moving_pixels == 0) return out;
  int best = 0;
  for (int c = 0; c < kCount; ++c) {
    consistent[c] /= out.moving_pixels;
    if (consistent[c] > consistent[best]) best = c;
  }
  out.as_given = {kCandidates[0].name, consistent[0]};
  out.best = {kCandidates[best].name, consistent[best]};
  if (out.moving_pixels >= kMinMoving && best != 0 && consistent[best] >= 0.6 &&
      consistent[best] > consistent[0] + 0.25) {
    // The convention that reads the vectors as the best candidate does: the candidate multiplies
    // both components by its sign and y by -1 when it flips y, on top of the given convention.
    const Candidate& k = kCandidates[best];
    MotionConvention fixed = given;
    if (k.sign < 0) fixed.previous_minus_current = !fixed.previous_minus_current;
    if (k.flip_y) fixed.y_up = !fixed.y_up;
    if (k.uv) fixed.units = MotionUnits::Uv;
    char text[480];
    std::snprintf(text, sizeof text,
                  "the vectors look %s: reprojected that way %.0f%% of %u moving pixels land on the same surface in "
                  "the previous frame, as given %.0f%%. Read them with %s",
                  k.name, 100 * consistent[best], out.moving_pixels, 100 * consistent[0],
                  motion_options(fixed).c_str());
    out.problem = text;
  }
  return out;
}

}  // namespace asvgf::cli
