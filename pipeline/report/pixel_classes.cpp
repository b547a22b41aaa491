#include "report/pixel_classes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "report/metrics.hpp"

namespace asvgf::report {

std::string_view to_string(PixelClass c) {
  switch (c) {
    case PixelClass::Background:
      return "background";
    case PixelClass::Edge:
      return "edges";
    case PixelClass::Coloured:
      return "coloured";
    case PixelClass::Grey:
      return "grey";
  }
  return "?";
}

namespace {

// Whether q lies on another surface than p, or on one of another albedo: depth beyond what p's
// plane predicts at that distance (twice its gradient, and 1%), normals more than about 8 degrees
// apart, or any albedo channel differing by more than 1e-3.
bool differs(std::span<const float> albedo, std::span<const float> depth, std::span<const float> normal, std::size_t p,
             std::size_t q, float distance) {
  const float zp = depth[4 * p], zq = depth[4 * q];
  if ((zp > 0) != (zq > 0)) return true;
  if (std::abs(zp - zq) > 2.0f * distance * depth[4 * p + 1] + 0.01f * zp) return true;
  float cos_pq = 0;
  for (int c = 0; c < 3; ++c) cos_pq += normal[4 * p + c] * normal[4 * q + c];
  if (cos_pq < 0.99f) return true;
  for (int c = 0; c < 3; ++c)
    if (std::abs(albedo[4 * p + c] - albedo[4 * q + c]) > 1e-3f) return true;
  return false;
}

}  // namespace

std::vector<PixelClass> classify_pixels(std::span<const float> albedo, std::span<const float> depth,
                                        std::span<const float> normal, std::uint32_t width, std::uint32_t height) {
  const std::size_t n = std::size_t(width) * height;
  if (albedo.size() != 4 * n || depth.size() != 4 * n || normal.size() != 4 * n)
    throw std::invalid_argument("classify_pixels: image sizes differ");
  constexpr int kEdgeRadius = 2;
  std::vector<PixelClass> classes(n, PixelClass::Background);
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t p = std::size_t(y) * width + x;
      if (!(depth[4 * p] > 0)) continue;
      bool edge = false;
      for (int dy = -kEdgeRadius; dy <= kEdgeRadius && !edge; ++dy)
        for (int dx = -kEdgeRadius; dx <= kEdgeRadius && !edge; ++dx) {
          const long qx = long(x) + dx, qy = long(y) + dy;
          if (qx < 0 || qy < 0 || qx >= long(width) || qy >= long(height)) continue;
          edge = differs(albedo, depth, normal, p, std::size_t(qy) * width + std::size_t(qx),
                         float(std::max(std::abs(dx), std::abs(dy))));
        }
      const float* a = &albedo[4 * p];
      const bool coloured = std::max({a[0], a[1], a[2]}) - std::min({a[0], a[1], a[2]}) > 0.05f;
      classes[p] = edge ? PixelClass::Edge : coloured ? PixelClass::Coloured : PixelClass::Grey;
    }
  return classes;
}

double ClassErrors::contribution(PixelClass c) const {
  const auto i = std::size_t(c);
  return fraction[i] > 0 ? fraction[i] * relmse[i] : 0.0;
}

ClassErrors relmse_by_class(std::span<const float> x, std::span<const float> r, std::span<const PixelClass> classes) {
  if (x.size() != r.size() || x.size() != 4 * classes.size())
    throw std::invalid_argument("relmse_by_class: sizes differ");
  std::array<double, kPixelClasses> sum{}, count{};
  for (std::size_t p = 0; p < classes.size(); ++p) {
    const auto k = std::size_t(classes[p]);
    count[k] += 1;
    for (int c = 0; c < 3; ++c) sum[k] += render::relative_squared_error(x[4 * p + c], r[4 * p + c]);
  }
  ClassErrors e;
  for (int k = 0; k < kPixelClasses; ++k) {
    e.fraction[k] = classes.empty() ? 0.0 : count[k] / double(classes.size());
    e.relmse[k] = count[k] > 0 ? sum[k] / (3.0 * count[k]) : std::numeric_limits<double>::quiet_NaN();
  }
  return e;
}

}  // namespace asvgf::report
