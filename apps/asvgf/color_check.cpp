#include "color_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "asvgf/denoiser.hpp"

namespace asvgf::cli {
namespace {

constexpr std::uint32_t kMinPixels = 64;
// An albedo counts as coloured where one channel differs from another by 20% or more.
constexpr double kColoured = 0.2;
// Measured on the first frames of the built-in scenes at 64x64 (render --aovs) and of Cycles
// sequences: demodulated colour -0.013..0.051, radiance 0.90..0.98.
constexpr double kDemodulatedBelow = 0.3;
constexpr double kRadianceAbove = 0.7;

}  // namespace

ColorKindCheck check_color_kind(std::span<const float> color, std::span<const float> albedo,
                                std::span<const float> depth, bool declared_radiance) {
  ColorKindCheck out;
  std::vector<double> xs, ys;  // albedo chromaticity, colour chromaticity (two entries a pixel)
  for (std::size_t i = 0; i + 3 < color.size(); i += 4) {
    if (asvgf::is_background_depth(depth[i])) continue;
    const double ar = albedo[i], ag = albedo[i + 1], ab = albedo[i + 2];
    const double cr = color[i], cg = color[i + 1], cb = color[i + 2];
    if (!(ar > 1e-3 && ag > 1e-3 && ab > 1e-3 && cr > 0 && cg > 0 && cb > 0)) continue;
    if (!std::isfinite(cr + cg + cb + ar + ag + ab)) continue;
    const double lo = std::min({ar, ag, ab}), hi = std::max({ar, ag, ab});
    if (hi < lo * (1 + kColoured)) continue;
    ++out.pixels;
    xs.push_back(std::log(ar / ag)), ys.push_back(std::log(cr / cg));
    xs.push_back(std::log(ab / ag)), ys.push_back(std::log(cb / cg));
  }
  if (out.pixels < kMinPixels) return out;
  const double n = double(xs.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) mx += xs[k] / n, my += ys[k] / n;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    sxy += (xs[k] - mx) * (ys[k] - my);
    sxx += (xs[k] - mx) * (xs[k] - mx);
    syy += (ys[k] - my) * (ys[k] - my);
  }
  out.correlation = sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : 0;
  char text[320];
  if (declared_radiance && out.correlation < kDemodulatedBelow) {
    std::snprintf(text, sizeof text,
                  "the colour looks demodulated (already divided by the albedo): its chromaticity follows the "
                  "albedo's with correlation %.2f over %u coloured pixels. Add --demodulated",
                  out.correlation, out.pixels);
    out.problem = text;
  } else if (!declared_radiance && out.correlation > kRadianceAbove) {
    std::snprintf(text, sizeof text,
                  "the colour looks like radiance (not divided by the albedo): its chromaticity follows the "
                  "albedo's with correlation %.2f over %u coloured pixels. Drop --demodulated",
                  out.correlation, out.pixels);
    out.problem = text;
  }
  return out;
}

}  // namespace asvgf::cli
