#include "denoiser/api/input_report.hpp"

#include <cstdio>
#include <string>

namespace asvgf::api {
namespace {

std::string percent(std::uint32_t part, std::uint32_t whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", whole ? 100.0 * part / whole : 0.0);
  return text;
}

// "N pixels (P%)"
std::string share(std::uint32_t part, std::uint32_t whole) {
  return std::to_string(part) + " pixel" + (part == 1 ? "" : "s") + " (" + percent(part, whole) + ")";
}

}  // namespace

InputReport make_input_report(const std::array<std::uint32_t, passes::kInputCounts>& c) {
  using namespace passes;
  InputReport r;
  r.pixels = c[kPixels];
  r.surface_pixels = c[kSurfacePixels];
  r.illumination_not_finite = c[kIlluminationNotFinite];
  r.illumination_negative = c[kIlluminationNegative];
  r.illumination_above_fp16 = c[kIlluminationAboveFp16];
  r.albedo_invalid = c[kAlbedoInvalid];
  r.normal_not_unit = c[kNormalNotUnit];
  r.normal_not_finite = c[kNormalNotFinite];
  r.depth_not_finite = c[kDepthNotFinite];
  r.depth_negative = c[kDepthNegative];
  r.motion_not_finite = c[kMotionNotFinite];
  r.moving_pixels = c[kMovingPixels];
  r.moving_consistent = c[kMovingConsistent];
  r.moving_consistent_negated = c[kMovingConsistentNegated];

  auto& p = r.problems;
  const std::uint32_t all = r.pixels, surface = r.surface_pixels;
  if (r.illumination_not_finite)
    p.push_back("illumination is NaN or Inf at " + share(r.illumination_not_finite, all) +
                " (those samples are dropped)");
  if (r.illumination_negative)
    p.push_back("illumination is negative at " + share(r.illumination_negative, all) + " (clamped to 0)");
  if (r.illumination_above_fp16)
    p.push_back("illumination exceeds 65504 at " + share(r.illumination_above_fp16, all) +
                " (clamped: the histories are half floats)");
  if (r.albedo_invalid) p.push_back("albedo is NaN, Inf or negative at " + share(r.albedo_invalid, all));
  if (r.depth_not_finite)
    p.push_back("depth is NaN or Inf at " + share(r.depth_not_finite, all) + " (treated as background: use 0)");
  if (r.depth_negative)
    p.push_back("depth is negative at " + share(r.depth_negative, all) +
                " (treated as background: linear view depth is positive, background 0)");
  if (all && surface == 0)
    p.push_back("every pixel is background (depth 0, negative or not finite): is depth bound to the right image?");
  if (r.normal_not_finite)
    p.push_back("normals are NaN or Inf at " + share(r.normal_not_finite, surface) +
                " of surface pixels (treated as background)");
  if (surface && r.normal_not_unit * 10 >= surface)  // a few percent are quantisation or bad meshes
    p.push_back("normals are not unit length at " + percent(r.normal_not_unit, surface) +
                " of surface pixels (world-space xyz expected, not encoded to [0, 1] or octahedral)");
  if (r.motion_not_finite) p.push_back("motion vectors are NaN or Inf at " + share(r.motion_not_finite, all));
  // The sign mistake shows as the negated vectors fitting the depths clearly better.
  const std::uint32_t m = r.moving_pixels;
  if (m >= 32 && r.moving_consistent_negated >= 0.6 * m && r.moving_consistent_negated > r.moving_consistent + 0.25 * m)
    p.push_back("motion vectors look negated: followed as given, " + percent(r.moving_consistent, m) + " of " +
                std::to_string(m) + " moving pixels land on the same surface in the previous frame, negated " +
                percent(r.moving_consistent_negated, m) +
                "; the denoiser needs previous minus current position, in pixels");
  return r;
}

}  // namespace asvgf::api
