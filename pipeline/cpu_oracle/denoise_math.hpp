// cpu_oracle/denoise_math.hpp: the C++ twin (double precision) of shaders/common/color.glsl and
// shaders/common/denoise.glsl: same constants, same guards, same tap weights.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include "cpu_oracle/octahedral.hpp"

namespace asvgf::reference {

inline constexpr double kFp16Max = 65504.0;
inline constexpr double kDepthEpsRel = 1e-3;
inline constexpr double kLumEps = 1e-10;
inline constexpr double kReprojDepthRel = 0.02;
inline constexpr double kReprojDepthGrad = 4.0;
inline constexpr double kReprojNormalCos = 0.9;

inline double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
inline bool any_not_finite(double r, double g, double b) {
  return !std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b);
}
inline double clamp_sample(double v) { return std::clamp(v, 0.0, kFp16Max); }
inline double clamp_fp16(double v) { return std::clamp(v, -kFp16Max, kFp16Max); }

struct Surface {
  double z = 0, dz = 0;
  std::array<double, 3> n{0, 0, 1};
  bool hit() const { return z > 0; }
};
// From a depth_normal texel (z, dz, octahedral normal).
inline Surface surface_from(double z, double dz, double ex, double ey) {
  return {z, dz, oct_decode<double>({ex, ey})};
}
inline double dot3(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline double weight_depth(const Surface& p, const Surface& q, double dist_l1, double sigma_z) {
  if (!q.hit()) return 0;
  const double tolerance = std::max(sigma_z * p.dz * dist_l1, kDepthEpsRel * p.z);
  return std::exp(-std::abs(p.z - q.z) / tolerance);
}
inline double weight_normal(const Surface& p, const Surface& q, double sigma_n) {
  return std::pow(std::clamp(dot3(p.n, q.n), 0.0, 1.0), sigma_n);
}
inline double weight_luminance(double lp, double lq, double sigma_l, double std_dev) {
  return std::exp(-std::abs(lp - lq) / (sigma_l * std_dev + kLumEps));
}
inline double b3spline(int i) { return i == 0 ? 0.375 : (std::abs(i) == 1 ? 0.25 : 0.0625); }
inline double binomial3(int i) { return i == 0 ? 0.5 : 0.25; }

inline bool reprojection_consistent(const Surface& cur, const Surface& prev) {
  if (!prev.hit()) return false;
  if (std::abs(cur.z - prev.z) > kReprojDepthRel * cur.z + kReprojDepthGrad * cur.dz) return false;
  return dot3(cur.n, prev.n) >= kReprojNormalCos;
}

}  // namespace asvgf::reference
