#include "report/metrics.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

namespace asvgf::render {

double relative_mse(std::span<const float> x, std::span<const float> r) {
  if (x.size() != r.size() || x.size() % 4 != 0) throw std::invalid_argument("relative_mse: image sizes differ");
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); i += 4)
    for (int c = 0; c < 3; ++c) sum += relative_squared_error(x[i + c], r[i + c]);
  return sum / double(x.size() / 4 * 3);
}

double relative_mse(std::span<const float> x, std::span<const float> r, std::span<const std::uint8_t> mask,
                    bool selected) {
  if (x.size() != r.size() || x.size() != mask.size() * 4) throw std::invalid_argument("relative_mse: sizes differ");
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t p = 0; p < mask.size(); ++p) {
    if ((mask[p] != 0) != selected) continue;
    ++n;
    for (int c = 0; c < 3; ++c) sum += relative_squared_error(x[4 * p + c], r[4 * p + c]);
  }
  return n == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / double(n * 3);
}

double ssim(std::span<const float> x, std::span<const float> r, std::uint32_t w, std::uint32_t h) {
  if (x.size() != r.size() || x.size() != std::size_t(w) * h * 4)
    throw std::invalid_argument("ssim: image sizes differ");
  auto lum = [](std::span<const float> img, std::size_t p) {
    const double l = 0.2126 * img[4 * p] + 0.7152 * img[4 * p + 1] + 0.0722 * img[4 * p + 2];
    return std::max(l, 0.0) / (1.0 + std::max(l, 0.0));
  };
  std::vector<double> a(std::size_t(w) * h), b(a.size());
  for (std::size_t p = 0; p < a.size(); ++p) a[p] = lum(x, p), b[p] = lum(r, p);
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  const int radius = 3;
  double total = 0.0;
  for (std::uint32_t py = 0; py < h; ++py)
    for (std::uint32_t px = 0; px < w; ++px) {
      double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
      int n = 0;
      for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
          const int qx = int(px) + dx, qy = int(py) + dy;
          if (qx < 0 || qy < 0 || qx >= int(w) || qy >= int(h)) continue;
          const double va = a[std::size_t(qy) * w + qx], vb = b[std::size_t(qy) * w + qx];
          sa += va, sb += vb, saa += va * va, sbb += vb * vb, sab += va * vb;
          ++n;
        }
      const double ma = sa / n, mb = sb / n;
      const double va = saa / n - ma * ma, vb = sbb / n - mb * mb, cov = sab / n - ma * mb;
      total += ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
    }
  return total / (double(w) * h);
}

double mean_value(std::span<const float> x) {
  double sum = 0.0;
  for (std::size_t i = 0; i < x.size(); i += 4) sum += double(x[i]) + x[i + 1] + x[i + 2];
  return x.empty() ? 0.0 : sum / double(x.size() / 4 * 3);
}

}  // namespace asvgf::render
